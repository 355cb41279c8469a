// SPDX-License-Identifier: MIT
// The litkit playground (docs/web.md): the scene text in, litkit's CPU
// renderer (WebAssembly, litkit.wasm) draws it, the picture out. Every
// picture comes from the text as `litkit render` reads it, with the model
// menus acting as --reflection and --shading.
"use strict";

(async () => {
  const $ = (id) => document.getElementById(id);
  const editor = $("scene-text");
  const picture = $("picture");
  const grid = $("grid");
  const status = $("status");
  const examples = window.LITKIT_EXAMPLES || { scenes: {}, meshes: {} };

  const module = await createLitkit();
  const call = (name, ...args) => {
    const types = args.map((a) => (typeof a === "number" ? "number" : "string"));
    return JSON.parse(module.ccall(name, "string", types, args));
  };
  const models = call("litkit_models");

  // The examples' meshes, where their scenes' relative `file` paths find
  // them: beside /scene/scene.toml, the scene the module reads.
  module.FS.mkdirTree("/scene/meshes");
  for (const [path, text] of Object.entries(examples.meshes)) module.FS.writeFile(`/scene/${path}`, text);

  // Menus.
  const exampleMenu = $("example");
  exampleMenu.add(new Option("default scene (litkit init)", ""));
  for (const name of Object.keys(examples.scenes)) exampleMenu.add(new Option(name, name));
  for (const name of models.reflection) $("reflection").add(new Option(name, name));
  for (const name of models.shading) $("shading").add(new Option(name, name));

  const page = {
    answers: 0,          // calls of litkit_render, successful or not
    renders: 0,          // successful renders of the text
    last: null,          // the last answer of litkit_render
    lastGood: null,      // the last successful one
    renderMs: null,      // time of the last litkit_render call, page side
    pending: null,       // a debounced render not yet run
    models,
  };
  window.playground = page;

  const view = () => document.querySelector('input[name="view"]:checked').value;

  function showDiagnostics(list, element) {
    element.replaceChildren();
    for (const d of list) {
      const item = document.createElement("li");
      item.textContent = d.line ? `line ${d.line}, column ${d.column}: ${d.message}` : d.message;
      item.dataset.line = d.line;
      item.dataset.column = d.column;
      item.title = d.text;
      element.append(item);
    }
  }

  function paint(canvas, answer, left = 0, top = 0) {
    // A view of the module's memory, copied once, by putImageData.
    const bytes = new Uint8ClampedArray(module.HEAPU8.buffer, module.ccall("litkit_pixels", "number", [], []),
                                        answer.width * answer.height * 4);
    canvas.getContext("2d").putImageData(new ImageData(bytes, answer.width, answer.height), left, top);
  }

  // The grid view: every reflection × shading pair, as `litkit compare`
  // draws it (each tile is `render` with those models for every object), at a
  // quarter of the output size; the labels are the page's.
  const gridLayout = { left: 110, top: 26, tileWidth: 0, tileHeight: 0 };
  function drawGrid(answer) {
    const tw = Math.max(1, Math.floor(answer.width / 4));
    const th = Math.max(1, Math.floor(answer.height / 4));
    Object.assign(gridLayout, { tileWidth: tw, tileHeight: th });
    grid.width = gridLayout.left + tw * models.shading.length;
    grid.height = gridLayout.top + th * models.reflection.length;
    const context = grid.getContext("2d");
    context.fillStyle = "#18181c";
    context.fillRect(0, 0, grid.width, grid.height);
    context.fillStyle = "#ebebeb";
    context.font = "14px sans-serif";
    context.textBaseline = "middle";
    models.shading.forEach((name, c) => {
      context.textAlign = "center";
      context.fillText(name, gridLayout.left + tw * (c + 0.5), gridLayout.top / 2);
    });
    models.reflection.forEach((reflection, r) => {
      context.textAlign = "right";
      context.fillText(reflection, gridLayout.left - 8, gridLayout.top + th * (r + 0.5));
      models.shading.forEach((shading, c) => {
        const tile = call("litkit_render_tile", reflection, shading, tw, th);
        if (tile.ok) paint(grid, tile, gridLayout.left + c * tw, gridLayout.top + r * th);
      });
    });
  }

  function showValues(answer) {
    const values = answer.values || {};
    const room = values.room || [10, 10, 10];
    for (const input of document.querySelectorAll("#sliders input")) {
      const path = input.dataset.path;
      let value;
      if (path.startsWith("objects[0].material.")) {
        const key = path.split(".").pop();
        value = values.material && values.material[key];
        if (key === "color" && value) {
          value = "#" + value.map((c) => Math.round(c).toString(16).padStart(2, "0")).join("");
        }
      } else if (path === "lights[0].intensity") {
        value = values.light && values.light.intensity;
      } else if (path === "lights[0].position") {
        const axis = Number(input.dataset.axis);
        input.min = -room[axis] / 2;
        input.max = room[axis] / 2;
        value = values.light && values.light.position && values.light.position[axis];
      }
      input.disabled = value === undefined;
      if (value !== undefined && document.activeElement !== input) input.value = value;
      const output = input.parentElement.querySelector("output");
      if (output) output.textContent = value === undefined ? "–" : input.value;
    }
  }

  // Renders the editor's text now. On an error the last good picture stays
  // and the errors, located, are listed under the editor.
  function render() {
    clearTimeout(page.pending);
    page.pending = null;
    const start = performance.now();
    const answer = call("litkit_render", editor.value, $("reflection").value, $("shading").value,
                        Number($("samples").value));
    page.last = answer;
    page.answers += 1;
    showDiagnostics(answer.ok ? [] : answer.errors, $("errors"));
    showDiagnostics(answer.warnings || [], $("warnings"));
    if (!answer.ok) {
      status.classList.add("stale");
      status.textContent = "The scene has errors: the picture is the last one that rendered.";
      return answer;
    }
    // (Setting a canvas's size clears and reallocates it: only on a change.)
    if (picture.width !== answer.width) picture.width = answer.width;
    if (picture.height !== answer.height) picture.height = answer.height;
    paint(picture, answer);
    page.renderMs = performance.now() - start;
    page.lastGood = answer;
    page.renders += 1;
    status.classList.remove("stale");
    status.textContent = `${answer.width}×${answer.height}, rendered in ${answer.ms.toFixed(1)} ms ` +
      `(${page.renderMs.toFixed(1)} ms with reading the text), ${answer.threads} thread` +
      (answer.lighting_given ? "" : "; [lighting] leaves a model out: phong used, as --yes does");
    showValues(answer);
    if (view() === "grid") drawGrid(answer);
    // The pixel last clicked, explained again for the scene as it is now
    // (watch its numbers follow a slider).
    if (page.explained && page.explained.ok && view() === "single" &&
        page.explained.x < answer.width && page.explained.y < answer.height) {
      explain(page.explained.x, page.explained.y);
    }
    return answer;
  }
  page.render = render;

  function scheduleRender() {
    clearTimeout(page.pending);
    page.pending = setTimeout(render, 150);
  }

  editor.addEventListener("input", scheduleRender);
  const showCaret = () => {
    const before = editor.value.slice(0, editor.selectionStart).split("\n");
    $("caret").textContent = `line ${before.length}, column ${before[before.length - 1].length + 1}`;
  };
  editor.addEventListener("keyup", showCaret);
  editor.addEventListener("click", showCaret);
  $("errors").addEventListener("click", (event) => {
    const item = event.target.closest("li");
    if (!item || !Number(item.dataset.line)) return;
    const offset = LitkitSliders.offsetOf(editor.value, Number(item.dataset.line), Number(item.dataset.column));
    editor.focus();
    editor.setSelectionRange(offset, offset);
    showCaret();
  });

  exampleMenu.addEventListener("change", () => {
    editor.value = exampleMenu.value ? examples.scenes[exampleMenu.value] : models.default_scene;
    render();
  });
  $("reflection").addEventListener("change", render);
  $("shading").addEventListener("change", render);
  $("samples").addEventListener("change", render);
  for (const radio of document.querySelectorAll('input[name="view"]')) {
    radio.addEventListener("change", () => {
      picture.hidden = view() === "grid";
      grid.hidden = view() !== "grid";
      render();
    });
  }

  // Sliders: the value goes into the text, and the text is rendered.
  for (const input of document.querySelectorAll("#sliders input")) {
    input.addEventListener("input", () => {
      const answer = page.lastGood;
      if (!answer) return;
      const path = input.dataset.path;
      let value;
      if (input.type === "color") {
        value = `"${input.value}"`;
      } else if (path === "lights[0].position") {
        const position = answer.values.light.position.slice();
        position[Number(input.dataset.axis)] = Number(input.value);
        value = `[${position.map((c) => LitkitSliders.number(c, 3)).join(", ")}]`;
      } else {
        value = LitkitSliders.number(input.value, 2);
      }
      const text = LitkitSliders.setValue(editor.value, answer.locations, path, value);
      if (text === null) return;
      editor.value = text;
      render();
    });
  }

  // Click on the picture: that pixel explained, as `litkit explain`.
  picture.addEventListener("click", (event) => {
    const x = Math.floor((event.offsetX * picture.width) / picture.clientWidth);
    const y = Math.floor((event.offsetY * picture.height) / picture.clientHeight);
    explain(x, y);
  });
  function explain(x, y) {
    const answer = call("litkit_explain", x, y);
    $("explanation").textContent = answer.ok
      ? `pixel (${x}, ${y}) = [${answer.rgb.join(", ")}]\n\n${answer.text}`
      : answer.errors.map((e) => e.message).join("\n");
    page.explained = answer;
    return answer;
  }
  page.explain = explain;

  // Click on a grid tile: that pair in the menus, the picture view.
  grid.addEventListener("click", (event) => {
    const x = (event.offsetX * grid.width) / grid.clientWidth - gridLayout.left;
    const y = (event.offsetY * grid.height) / grid.clientHeight - gridLayout.top;
    const c = Math.floor(x / gridLayout.tileWidth);
    const r = Math.floor(y / gridLayout.tileHeight);
    if (x < 0 || y < 0 || c >= models.shading.length || r >= models.reflection.length) return;
    $("reflection").value = models.reflection[r];
    $("shading").value = models.shading[c];
    document.querySelector('input[name="view"][value="single"]').click();
  });

  // OBJ files: written beside the scene, so `file = "name.obj"` finds them.
  async function addMeshFile(file) {
    const name = file.name.replace(/.*[\\/]/, "").replace(/[^A-Za-z0-9._-]/g, "_") || "mesh.obj";
    module.FS.writeFile(`/scene/${name}`, new Uint8Array(await file.arrayBuffer()));
    module.ccall("litkit_forget_meshes", null, [], []);
    page.files = (page.files || []).filter((f) => f !== name).concat(name);
    $("files").textContent = `Files beside the scene: ${page.files.join(", ")} ` +
      `(use one with type = "mesh" and file = "${name}")`;
    render();
    return name;
  }
  page.addMeshFile = addMeshFile;
  $("obj-file").addEventListener("change", (event) => {
    for (const file of event.target.files) addMeshFile(file);
  });
  editor.addEventListener("dragover", (event) => {
    event.preventDefault();
    editor.classList.add("dragging");
  });
  editor.addEventListener("dragleave", () => editor.classList.remove("dragging"));
  editor.addEventListener("drop", (event) => {
    event.preventDefault();
    editor.classList.remove("dragging");
    for (const file of event.dataTransfer.files) addMeshFile(file);
  });

  editor.value = models.default_scene;
  render();
  page.ready = true;
  document.body.dataset.ready = "true";
})();
