// SPDX-License-Identifier: MIT
// The sliders write into the scene text, so that the text stays the one
// description of the picture (what `litkit render` of it draws). The module
// tells where each value is written (line, column of the value, from the
// scene's locations); a value the text leaves out is added to its table.
"use strict";

const LitkitSliders = (() => {
  // Offset in `text` of 1-based (line, column).
  function offsetOf(text, line, column) {
    let offset = 0;
    for (let l = 1; l < line; ++l) {
      const next = text.indexOf("\n", offset);
      if (next < 0) return text.length;
      offset = next + 1;
    }
    return Math.min(offset + column - 1, text.length);
  }

  // Where the TOML value starting at `start` ends: an array to its matching
  // bracket, a string to its quote, anything else to a separator.
  function valueEnd(text, start) {
    const first = text[start];
    if (first === "[") {
      let depth = 0;
      for (let i = start; i < text.length; ++i) {
        if (text[i] === "[") ++depth;
        else if (text[i] === "]" && --depth === 0) return i + 1;
      }
      return text.length;
    }
    if (first === '"' || first === "'") {
      const close = text.indexOf(first, start + 1);
      return close < 0 ? text.length : close + 1;
    }
    let i = start;
    while (i < text.length && !/[\s,}\]#]/.test(text[i])) ++i;
    return i;
  }

  function lineEnd(text, offset) {
    const next = text.indexOf("\n", offset);
    return next < 0 ? text.length : next;
  }

  // Adds `key = value` to the table whose definition starts at `offset`:
  // inside an inline table's braces, else on the line after its header.
  function addToTable(text, offset, key, value) {
    if (text[offset] === "{") {
      const inner = text.slice(offset + 1).trimStart();
      const separator = inner.startsWith("}") ? " " : ", ";
      return text.slice(0, offset + 1) + ` ${key} = ${value}${separator}` +
             text.slice(offset + 1).replace(/^\s*/, "");
    }
    const end = lineEnd(text, offset);
    return text.slice(0, end) + `\n${key} = ${value}` + text.slice(end);
  }

  // The text with the value at `path` ("objects[0].material.kd") set to
  // `value` (TOML text), or null when the table to hold it is not there.
  function setValue(text, locations, path, value) {
    const at = locations[path];
    if (at) {
      const start = offsetOf(text, at[0], at[1]);
      return text.slice(0, start) + value + text.slice(valueEnd(text, start));
    }
    const dot = path.lastIndexOf(".");
    const parent = path.slice(0, dot);
    const key = path.slice(dot + 1);
    if (locations[parent]) return addToTable(text, offsetOf(text, ...locations[parent]), key, value);
    // A material the object leaves out entirely.
    const grandDot = parent.lastIndexOf(".");
    const owner = parent.slice(0, grandDot);
    if (grandDot > 0 && locations[owner]) {
      const tableKey = parent.slice(grandDot + 1);
      return addToTable(text, offsetOf(text, ...locations[owner]), tableKey, `{ ${key} = ${value} }`);
    }
    return null;
  }

  // Numbers as a person would write them: no trailing zeros, no "-0".
  function number(value, decimals) {
    const text = Number(value).toFixed(decimals).replace(/(\.\d*?)0+$/, "$1").replace(/\.$/, "");
    return text === "-0" ? "0" : text;
  }

  return { offsetOf, valueEnd, setValue, number };
})();
