// SPDX-License-Identifier: MIT
// Times the playground's rendering in headless Chromium (docs/performance.md,
// "The web playground"): the default scene at 800x600, drawn again and again
// through the page's own path (litkit_render: read and validate the text,
// render, RGBA, canvas). Run by bench/web.sh; prints the median and the
// fastest of the runs, for the render alone and for the page's whole call.
//   node bench/web.mjs SITE_DIR [RUNS]
import path from "node:path";
import { launch, openPlayground, serve } from "../tests/web/lib.mjs";

const site = path.resolve(process.argv[2]);
const runs = Number(process.argv[3] || 40);
const server = await serve(site);
const browser = await launch();
try {
  const { page } = await openPlayground(browser, server.url);
  const result = await page.evaluate((runs) => {
    const renderMs = [], pageMs = [], parseMs = [];
    for (let i = 0; i < runs + 5; ++i) {
      const answer = window.playground.render();
      if (!answer.ok) throw new Error("render failed");
      if (i < 5) continue;  // warm-up: the engine's compilers settle
      renderMs.push(answer.ms);
      parseMs.push(answer.parse_ms);
      pageMs.push(window.playground.renderMs);
    }
    const stats = (list) => {
      const sorted = list.slice().sort((a, b) => a - b);
      return { median: sorted[Math.floor(sorted.length / 2)], min: sorted[0] };
    };
    const last = window.playground.last;
    return { size: `${last.width}x${last.height}`, threads: last.threads, render: stats(renderMs), parse: stats(parseMs),
             page: stats(pageMs) };
  }, runs);
  const f = (v) => v.toFixed(1);
  console.log(`default scene ${result.size}, ${result.threads} thread, ${runs} runs in ${await browser.version()}`);
  console.log(`render (Renderer::render_into): median ${f(result.render.median)} ms, min ${f(result.render.min)} ms`);
  console.log(`reading and validating the text (parse_scene): median ${f(result.parse.median)} ms, ` +
              `min ${f(result.parse.min)} ms`);
  console.log(`page's whole call (parse, validate, render, canvas): median ${f(result.page.median)} ms, ` +
              `min ${f(result.page.min)} ms`);
} finally {
  await browser.close();
  await server.close();
}
