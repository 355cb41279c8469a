// SPDX-License-Identifier: MIT
// web/site/sliders.js on its own (no browser): how a slider's value goes
// into the scene text, where the value is written and where it is not.
//   node sliders.test.mjs SITE_DIR_OR_WEB_SITE
// Prints one line per check and "N passed, M failed".
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";

const source = fs.readFileSync(path.join(process.argv[2], "sliders.js"), "utf8");
const context = {};
vm.runInNewContext(`${source}\nthis.LitkitSliders = LitkitSliders;`, context);
const { setValue, number } = context.LitkitSliders;

let passed = 0, failed = 0;
function check(name, actual, expected) {
  if (actual === expected) {
    ++passed;
    console.log(`ok   ${name}`);
  } else {
    ++failed;
    console.log(`FAIL ${name}\n     expected ${JSON.stringify(expected)}\n     got      ${JSON.stringify(actual)}`);
  }
}

// Locations as the module reports them: [line, column] of each value.
const inline = '[[objects]]\ntype = "cube"\nmaterial = { color = [200, 80, 60], kd = 0.7 }\n';
check("a number inside an inline table is replaced",
      setValue(inline, { "objects[0].material.kd": [3, 42] }, "objects[0].material.kd", "0.3"),
      '[[objects]]\ntype = "cube"\nmaterial = { color = [200, 80, 60], kd = 0.3 }\n');
check("an array value is replaced whole",
      setValue(inline, { "objects[0].material.color": [3, 22] }, "objects[0].material.color", '"#102030"'),
      '[[objects]]\ntype = "cube"\nmaterial = { color = "#102030", kd = 0.7 }\n');
check("a key the inline table leaves out is added inside its braces",
      setValue(inline, { "objects[0]": [1, 1], "objects[0].material": [3, 12] }, "objects[0].material.ks", "0.5"),
      '[[objects]]\ntype = "cube"\nmaterial = { ks = 0.5, color = [200, 80, 60], kd = 0.7 }\n');
const noMaterial = '[[objects]]\ntype = "cube"\n\n[[lights]]\ntype = "point"\nposition = [0, 1, 0] # here\n';
check("an object without a material gets one on the line after its header",
      setValue(noMaterial, { "objects[0]": [1, 1] }, "objects[0].material.ka", "0.2"),
      '[[objects]]\nmaterial = { ka = 0.2 }\ntype = "cube"\n\n[[lights]]\ntype = "point"\nposition = [0, 1, 0] # here\n');
check("a light's missing intensity goes on the line after its header",
      setValue(noMaterial, { "lights[0]": [4, 1] }, "lights[0].intensity", "12"),
      '[[objects]]\ntype = "cube"\n\n[[lights]]\nintensity = 12\ntype = "point"\nposition = [0, 1, 0] # here\n');
check("a value followed by a comment keeps the comment",
      setValue(noMaterial, { "lights[0].position": [6, 12] }, "lights[0].position", "[1, 2, 3]"),
      '[[objects]]\ntype = "cube"\n\n[[lights]]\ntype = "point"\nposition = [1, 2, 3] # here\n');
check("no table to hold the value: no change (null)", setValue(noMaterial, {}, "lights[0].intensity", "1"), null);
check("numbers without trailing zeros", [number(0.5, 2), number(1, 2), number(-0.001, 2), number(2.25, 1)].join(" "),
      "0.5 1 0 2.3");

console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
