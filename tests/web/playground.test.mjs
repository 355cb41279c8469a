// SPDX-License-Identifier: MIT
// Drives the built playground (build-web/site) in Debian's headless Chromium
// and checks it against the native `litkit` (scripts/test-web.sh runs it):
//   node playground.test.mjs SITE_DIR LITKIT REPO_ROOT [SCREENSHOT]
// Every picture is compared with `litkit render` of the same text, pixel for
// pixel. Prints one line per check and "N passed, M failed"; exits 1 on any
// failure.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { canvasPixels, difference, launch, litkitRender, openPlayground, serve } from "./lib.mjs";

const [site, litkit, root, screenshot] = process.argv.slice(2).map((p) => p && path.resolve(p));
const examples = path.join(root, "examples");
const exampleMeshes = Object.fromEntries(
  fs.readdirSync(path.join(examples, "meshes")).map((n) => [`meshes/${n}`, path.join(examples, "meshes", n)]));

let passed = 0, failed = 0;
async function check(name, body) {
  try {
    await body();
    ++passed;
    console.log(`ok   ${name}`);
  } catch (error) {
    ++failed;
    console.log(`FAIL ${name}\n     ${String(error.stack || error).split("\n").join("\n     ")}`);
  }
}
function expect(condition, message) {
  if (!condition) throw new Error(message);
}
function expectSame(actual, expected, what) {
  const d = difference(actual, expected);
  expect(d === null, `${what}: ${d}`);
}

const server = await serve(site);
const browser = await launch();
try {
  const { page, problems } = await openPlayground(browser, server.url);

  // Helpers that act as a user would and wait for the page's answer.
  const answers = () => page.evaluate(() => window.playground.answers);
  async function settle(before) {
    await page.waitForFunction((n) => window.playground.answers > n && window.playground.pending === null,
                               { timeout: 30000 }, before);
  }
  async function typeText(text) {
    const before = await answers();
    await page.evaluate((text) => {
      const editor = document.getElementById("scene-text");
      editor.value = text;
      editor.dispatchEvent(new Event("input", { bubbles: true }));
    }, text);
    await settle(before);  // the debounced render
  }
  const editorText = () => page.$eval("#scene-text", (e) => e.value);
  const lastAnswer = () => page.evaluate(() => window.playground.last);
  async function choose(selector, value) {
    const before = await answers();
    await page.select(selector, value);
    await settle(before);
  }

  await check("the page loads, renders with one thread and reports no script error", async () => {
    const answer = await lastAnswer();
    expect(answer.ok, `first render failed: ${JSON.stringify(answer.errors)}`);
    expect(answer.threads === 1, `threads: ${answer.threads}`);
    expect(problems.length === 0, `errors in the page: ${problems.join("; ")}`);
  });

  await check("the editor starts with the default scene, as `litkit init` writes it", async () => {
    const folder = fs.mkdtempSync(path.join(root, "build-web", "init-"));
    try {
      execFileSync(litkit, ["init", path.join(folder, "scene.toml")], { stdio: "ignore" });
      expect((await editorText()) === fs.readFileSync(path.join(folder, "scene.toml"), "utf8"),
             "the editor's text differs from litkit init's");
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  await check("default scene: the canvas equals `litkit render`, every pixel", async () => {
    const expected = litkitRender(litkit, await editorText());
    expect(expected.width === 800 && expected.height === 600, "litkit render is not 800x600");
    expectSame(await canvasPixels(page, "picture"), expected, "default scene");
  });

  await check("default scene: the canvas equals `litkit render` with no scene at all", async () => {
    const folder = fs.mkdtempSync(path.join(root, "build-web", "default-"));
    try {
      execFileSync(litkit, ["render", "-o", path.join(folder, "d.png")], { stdio: "ignore" });
      const { readPng } = await import("./lib.mjs");
      expectSame(await canvasPixels(page, "picture"), readPng(path.join(folder, "d.png")), "default");
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  await check("another scene typed in (examples/mesh.toml, two OBJ meshes) equals `litkit render`", async () => {
    const text = fs.readFileSync(path.join(examples, "mesh.toml"), "utf8");
    await typeText(text);
    const answer = await lastAnswer();
    expect(answer.ok, JSON.stringify(answer.errors));
    expectSame(await canvasPixels(page, "picture"), litkitRender(litkit, text, [], exampleMeshes), "mesh.toml");
  });

  await check("the examples menu: teapot.toml equals `litkit render examples/teapot.toml`", async () => {
    await choose("#example", "teapot.toml");
    const text = await editorText();
    expect(text === fs.readFileSync(path.join(examples, "teapot.toml"), "utf8"), "menu text differs");
    expectSame(await canvasPixels(page, "picture"), litkitRender(litkit, text), "teapot.toml");
  });

  // Every example under its own models.
  await check("every example equals `litkit render` of it", async () => {
    const failures = [];
    for (const name of fs.readdirSync(examples).filter((n) => n.endsWith(".toml")).sort()) {
      await choose("#example", name);
      const d = difference(await canvasPixels(page, "picture"),
                           litkitRender(litkit, await editorText(), [], exampleMeshes));
      if (d) failures.push(`${name}: ${d}`);
    }
    expect(failures.length === 0, failures.join("; "));
  });

  for (const [reflection, shading, example] of [["blinn-phong", "gouraud", "reflection-models.toml"],
                                                 ["cook-torrance", "flat", "teapot.toml"],
                                                 ["lambert", "faceted", "torus.toml"]]) {
    await check(`models ${reflection} + ${shading} (${example}) equal \`litkit render --reflection ` +
                `${reflection} --shading ${shading}\``, async () => {
      await choose("#example", example);
      await choose("#reflection", reflection);
      await choose("#shading", shading);
      const args = ["--reflection", reflection, "--shading", shading];
      expectSame(await canvasPixels(page, "picture"),
                 litkitRender(litkit, await editorText(), args, exampleMeshes), `${reflection}/${shading}`);
    });
  }
  // tests/web/turned.toml: rotations by 10000°, −1234.567° and 1e6°, shininess 10000, odd
  // powers (a spot's exponent 1.7, shininess 37.3), where sinf, cosf and powf of glibc and of
  // emscripten's musl can round differently; flat and gouraud shade on the scalar path.
  await check("large rotations and high shininess equal `litkit render`, every model with a power " +
              "under every shading", async () => {
    await typeText(fs.readFileSync(path.join(root, "tests", "web", "turned.toml"), "utf8"));
    const failures = [];
    for (const reflection of ["phong", "blinn-phong", "toon", "minnaert", "cook-torrance"]) {
      await choose("#reflection", reflection);
      for (const shading of ["flat", "gouraud", "phong"]) {
        await choose("#shading", shading);
        const args = ["--reflection", reflection, "--shading", shading];
        const d = difference(await canvasPixels(page, "picture"),
                             litkitRender(litkit, await editorText(), args));
        if (d) failures.push(`${reflection}/${shading}: ${d}`);
      }
    }
    expect(failures.length === 0, failures.join("; "));
  });
  await choose("#reflection", "");
  await choose("#shading", "");

  // Anti-aliasing (docs/spec.md §11): the samples menu acts as --samples.
  for (const [samples, example] of [["4", "reflection-models.toml"], ["16", "glass-lens.toml"]]) {
    await check(`samples ${samples} (${example}) equals \`litkit render --samples ${samples}\``, async () => {
      await choose("#example", example);
      await choose("#samples", samples);
      const text = await editorText();
      const picture = await canvasPixels(page, "picture");
      expectSame(picture, litkitRender(litkit, text, ["--samples", samples], exampleMeshes), `samples ${samples}`);
      expect(difference(picture, litkitRender(litkit, text, [], exampleMeshes)) !== null,
             "the picture with samples equals the one without");
    });
  }
  await choose("#samples", "0");
  await choose("#example", "");

  await check("an invalid value: the located error is shown and the picture is unchanged", async () => {
    const good = await canvasPixels(page, "picture");
    const text = await editorText();
    const bad = text.replace("intensity = 15", "intensity = -15");
    expect(bad !== text, "the default scene has no 'intensity = 15'");
    // Where the value is, counted here from the text.
    const offset = bad.indexOf("intensity = -15") + "intensity = ".length;
    const line = bad.slice(0, offset).split("\n").length;
    const column = offset - bad.lastIndexOf("\n", offset - 1);
    await typeText(bad);
    const errors = await page.$$eval("#errors li", (items) => items.map((i) => i.textContent));
    expect(errors.length >= 1, "no error listed under the editor");
    expect(errors.some((e) => e.startsWith(`line ${line}, column ${column}:`) && e.includes("intensity")),
           `expected an error at line ${line}, column ${column}; got ${JSON.stringify(errors)}`);
    // The command line reports the same place.
    let message = "";
    try {
      execFileSync(litkit, ["check", "-"], { input: bad, stdio: ["pipe", "pipe", "pipe"] });
    } catch (error) {
      message = String(error.stderr);
    }
    expect(message.includes(`:${line}:${column}:`), `litkit check says: ${message}`);
    expectSame(await canvasPixels(page, "picture"), good, "picture after the error");
    await typeText(text);
    expect((await page.$$("#errors li")).length === 0, "the error stays after the fix");
  });

  await check("a click on the picture explains that pixel, as `litkit explain --pixel` does", async () => {
    const target = [430, 330];
    await page.$eval("#picture", (c) => c.scrollIntoView());
    const box = await (await page.$("#picture")).boundingBox();
    const size = await page.$eval("#picture", (c) => [c.width, c.height]);
    await page.evaluate(() => { window.playground.explained = null; });
    await page.mouse.click(box.x + ((target[0] + 0.5) * box.width) / size[0],
                           box.y + ((target[1] + 0.5) * box.height) / size[1]);
    await page.waitForFunction(() => window.playground.explained, { timeout: 10000 });
    // The pixel under the mouse (the browser rounds the click's position).
    const { x, y } = await page.evaluate(() => window.playground.explained);
    expect(Math.abs(x - target[0]) <= 1 && Math.abs(y - target[1]) <= 1, `explained (${x}, ${y})`);
    const shown = await page.$eval("#explanation", (e) => e.textContent);
    const pixel = await canvasPixels(page, "picture", { x, y, width: 1, height: 1 });
    const rgb = [...pixel.rgb];
    expect(shown.startsWith(`pixel (${x}, ${y}) = [${rgb.join(", ")}]`), `shown: ${shown.slice(0, 80)}`);
    const folder = fs.mkdtempSync(path.join(root, "build-web", "explain-"));
    try {
      fs.writeFileSync(path.join(folder, "scene.toml"), await editorText());
      const cli = execFileSync(litkit, ["explain", path.join(folder, "scene.toml"), "--pixel", `${x},${y}`],
                               { encoding: "utf8" });
      const body = shown.slice(shown.indexOf("\n\n") + 2);
      expect(cli.includes(`rgb = round(255 * that) = (${rgb.join(", ")})`),
             `litkit explain does not end with the canvas's value ${rgb}:\n${cli}`);
      expect(body === cli, `the page's explanation differs from litkit explain:\n${body}\n---\n${cli}`);
    } finally {
      fs.rmSync(folder, { recursive: true, force: true });
    }
  });

  await check("sliders write into the text, and the picture is `litkit render` of the new text", async () => {
    const before = await answers();
    await page.$eval("#s-kd", (input) => {
      input.value = "0.3";
      input.dispatchEvent(new Event("input", { bubbles: true }));
    });
    await settle(before);
    const before2 = await answers();
    await page.$eval("#s-x", (input) => {
      input.value = "-1.5";
      input.dispatchEvent(new Event("input", { bubbles: true }));
    });
    await settle(before2);
    const text = await editorText();
    expect(/\bkd = 0\.3\b/.test(text), "kd = 0.3 is not in the text");
    expect(text.includes("position = [-1.5, 0, 0]"), "the light's position is not in the text");
    expectSame(await canvasPixels(page, "picture"), litkitRender(litkit, text), "after the sliders");
  });

  await check("grid view: each tile equals `litkit render` with that pair at a quarter of the size", async () => {
    await typeText(fs.readFileSync(path.join(examples, "sphere.toml"), "utf8"));
    const before = await answers();
    await page.click('input[name="view"][value="grid"]');
    await settle(before);
    const text = await editorText();
    const { width, height } = await lastAnswer();
    const [tw, th] = [Math.floor(width / 4), Math.floor(height / 4)];
    const models = await page.evaluate(() => window.playground.models);
    const layout = { left: 110, top: 26 };
    const grid = await page.$eval("#grid", (c) => [c.width, c.height]);
    expect(grid[0] === layout.left + tw * models.shading.length &&
           grid[1] === layout.top + th * models.reflection.length, `grid is ${grid}`);
    for (const [r, c] of [[0, 0], [3, 1], [models.reflection.length - 1, models.shading.length - 1]]) {
      const tile = await canvasPixels(page, "grid", { x: layout.left + c * tw, y: layout.top + r * th,
                                                      width: tw, height: th });
      const args = ["--reflection", models.reflection[r], "--shading", models.shading[c],
                    "--width", String(tw), "--height", String(th)];
      expectSame(tile, litkitRender(litkit, text, args), `tile ${models.reflection[r]}/${models.shading[c]}`);
    }
    if (screenshot) await page.screenshot({ path: screenshot, fullPage: true });
    const back = await answers();
    await page.click('input[name="view"][value="single"]');
    await settle(back);
  });

  await check("an OBJ file from the file picker is the scene's `file`", async () => {
    const input = await page.$("#obj-file");
    await input.uploadFile(path.join(examples, "meshes", "octahedron.obj"));
    await page.waitForFunction(() => (window.playground.files || []).includes("octahedron.obj"), { timeout: 30000 });
    const text = fs.readFileSync(path.join(examples, "mesh.toml"), "utf8")
      .replaceAll("meshes/icosahedron.obj", "octahedron.obj").replaceAll("meshes/octahedron.obj", "octahedron.obj");
    await typeText(text);
    const answer = await lastAnswer();
    expect(answer.ok, JSON.stringify(answer.errors));
    expectSame(await canvasPixels(page, "picture"),
               litkitRender(litkit, text, [], { "octahedron.obj": path.join(examples, "meshes", "octahedron.obj") }),
               "uploaded mesh");
  });

  await check("no script error in the page during the test", async () => {
    expect(problems.length === 0, problems.join("; "));
  });
} finally {
  await browser.close();
  await server.close();
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
