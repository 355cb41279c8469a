// SPDX-License-Identifier: MIT
// What the playground's test (playground.test.mjs) and benchmark
// (bench/web.mjs) share: a static file server for build-web/site, Debian's
// Chromium started headless through puppeteer-core (no browser download), a
// PNG reader for `litkit render`'s pictures and a way to run litkit.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import os from "node:os";
import path from "node:path";
import zlib from "node:zlib";
import puppeteer from "puppeteer-core";

const types = {
  ".html": "text/html", ".js": "text/javascript", ".css": "text/css",
  ".wasm": "application/wasm", ".png": "image/png",
};

// Serves `root` on a free port of 127.0.0.1; resolves to { url, close }.
export function serve(root) {
  const server = http.createServer((request, response) => {
    const name = decodeURIComponent(new URL(request.url, "http://x").pathname);
    const file = path.join(root, name.endsWith("/") ? name + "index.html" : name);
    if (!file.startsWith(root) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { "Content-Type": types[path.extname(file)] || "application/octet-stream" });
    fs.createReadStream(file).pipe(response);
  });
  return new Promise((resolve) => {
    server.listen(0, "127.0.0.1", () => resolve({
      url: `http://127.0.0.1:${server.address().port}/`,
      close: () => new Promise((done) => server.close(done)),
    }));
  });
}

export function chromiumPath() {
  for (const candidate of [process.env.CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"]) {
    if (candidate && fs.existsSync(candidate)) return candidate;
  }
  throw new Error("no Chromium: run scripts/install-deps.sh --web (Debian's chromium)");
}

export async function launch() {
  return puppeteer.launch({
    executablePath: chromiumPath(),
    headless: true,
    // --no-sandbox: CI runs as root, where Chromium's sandbox refuses to start.
    args: ["--no-sandbox", "--disable-gpu", "--window-size=1500,1100"],
    defaultViewport: { width: 1500, height: 1100 },
  });
}

// The page, loaded and ready (its first picture drawn).
export async function openPlayground(browser, url) {
  const page = await browser.newPage();
  const problems = [];
  page.on("pageerror", (error) => problems.push(String(error)));
  page.on("console", (message) => {
    if (message.type() === "error") problems.push(message.text());
  });
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => window.playground && window.playground.ready, { timeout: 60000 });
  return { page, problems };
}

// Reads an 8-bit RGB or RGBA, non-interlaced PNG: { width, height, rgb }.
export function readPng(file) {
  const bytes = fs.readFileSync(file);
  let offset = 8;
  let width = 0, height = 0, channels = 0;
  const data = [];
  while (offset < bytes.length) {
    const length = bytes.readUInt32BE(offset);
    const type = bytes.toString("latin1", offset + 4, offset + 8);
    const body = bytes.subarray(offset + 8, offset + 8 + length);
    if (type === "IHDR") {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      if (body[8] !== 8 || body[12] !== 0) throw new Error(`${file}: not 8-bit non-interlaced`);
      channels = { 2: 3, 6: 4 }[body[9]];
      if (!channels) throw new Error(`${file}: colour type ${body[9]}`);
    } else if (type === "IDAT") {
      data.push(body);
    }
    offset += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(data));
  const stride = width * channels;
  const pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? pixels[y * stride + i - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + i] : 0;
      const c = y > 0 && i >= channels ? pixels[(y - 1) * stride + i - channels] : 0;
      let value = line[i];
      if (filter === 1) value += a;
      else if (filter === 2) value += b;
      else if (filter === 3) value += (a + b) >> 1;
      else if (filter === 4) {
        const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        value += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      pixels[y * stride + i] = value & 255;
    }
  }
  const rgb = Buffer.alloc(width * height * 3);
  for (let i = 0; i < width * height; ++i) pixels.copy(rgb, i * 3, i * channels, i * channels + 3);
  return { width, height, rgb };
}

// `litkit render` of `text` (written to a scene file in a folder of its own,
// beside copies of `meshes`), with extra arguments: the picture it writes.
export function litkitRender(litkit, text, args = [], meshes = {}) {
  const folder = fs.mkdtempSync(path.join(os.tmpdir(), "litkit-web-"));
  try {
    for (const [name, source] of Object.entries(meshes)) {
      fs.mkdirSync(path.dirname(path.join(folder, name)), { recursive: true });
      fs.copyFileSync(source, path.join(folder, name));
    }
    fs.writeFileSync(path.join(folder, "scene.toml"), text);
    const output = path.join(folder, "out.png");
    execFileSync(litkit, ["render", path.join(folder, "scene.toml"), "-o", output, ...args],
                 { stdio: ["ignore", "ignore", "pipe"] });
    return readPng(output);
  } finally {
    fs.rmSync(folder, { recursive: true, force: true });
  }
}

// The RGB pixels of a canvas of the page, or of a rectangle of it.
export async function canvasPixels(page, id, rect = null) {
  const result = await page.evaluate((id, rect) => {
    const canvas = document.getElementById(id);
    const r = rect || { x: 0, y: 0, width: canvas.width, height: canvas.height };
    const data = canvas.getContext("2d").getImageData(r.x, r.y, r.width, r.height).data;
    let binary = "";
    for (let i = 0; i < data.length; i += 4) binary += String.fromCharCode(data[i], data[i + 1], data[i + 2]);
    return { width: r.width, height: r.height, rgb: btoa(binary) };
  }, id, rect);
  return { width: result.width, height: result.height, rgb: Buffer.from(result.rgb, "base64") };
}

// How two pictures differ: null when equal, else a sentence.
export function difference(a, b) {
  if (a.width !== b.width || a.height !== b.height)
    return `sizes differ: ${a.width}x${a.height} against ${b.width}x${b.height}`;
  let count = 0, first = -1, largest = 0;
  for (let i = 0; i < a.rgb.length; ++i) {
    const d = Math.abs(a.rgb[i] - b.rgb[i]);
    if (d) {
      if (first < 0) first = i;
      ++count;
      largest = Math.max(largest, d);
    }
  }
  if (!count) return null;
  const pixel = Math.floor(first / 3);
  return `${count} channel values differ (largest by ${largest}); first at pixel ` +
         `(${pixel % a.width}, ${Math.floor(pixel / a.width)})`;
}
