// The web build in a real browser: headless Chromium (Debian's) driven by
// playwright-core, the page served from web/dist on 127.0.0.1.
//
//   node web/tests/browser.mjs [DIST] [GRAINSCOPE_BINARY]
//
// Fails on any panic or console error. Checks that the canvas is drawn;
// opens a collision, a disk map (a heavy scene, computed in a Web Worker)
// and a deck slide by their links and compares the screenshots with the
// reviewed references in web/tests/references (UPDATE_REFERENCES=1 writes
// them); compares the numbers with the native binary's `--json`; drags a
// slider and sees the figure change; downloads an exported PNG and drops it
// on a fresh page, which reopens its state; runs a command from the palette. Screenshots go to $OUT
// (default web/test-output). Prints the budgets it measures.

import { chromium } from "playwright-core";
import { PNG } from "pngjs";
import pixelmatch from "pixelmatch";
import jsQR from "jsqr";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import zlib from "node:zlib";

const here = path.dirname(new URL(import.meta.url).pathname);
const dist = path.resolve(process.argv[2] ?? path.join(here, "..", "dist"));
const binary = process.argv[3] ?? null;
const out = path.resolve(process.env.OUT ?? path.join(here, "..", "test-output"));
const references = path.join(here, "references");
const update = process.env.UPDATE_REFERENCES === "1";
const size = { width: 1024, height: 768 };
fs.mkdirSync(out, { recursive: true });

const failures = [];
function fail(message) {
  failures.push(message);
  console.log(`FAIL ${message}`);
}
function ok(message) {
  console.log(`ok   ${message}`);
}

// --- a static server for web/dist ---------------------------------------
// As `python3 -m http.server`: no compression, Last-Modified and
// If-Modified-Since (a revalidated file is not sent again).
const types = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm", ".png": "image/png" };
function serve(root, port = 0) {
  const server = http.createServer((req, res) => {
    const name = decodeURIComponent(new URL(req.url, "http://x").pathname);
    const file = path.join(root, name === "/" ? "index.html" : name);
    if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404).end();
      return;
    }
    const modified = new Date(Math.floor(fs.statSync(file).mtimeMs / 1000) * 1000);
    const since = Date.parse(req.headers["if-modified-since"] ?? "");
    if (!Number.isNaN(since) && modified.getTime() <= since) {
      res.writeHead(304).end();
      return;
    }
    res.writeHead(200, {
      "Content-Type": types[path.extname(file)] ?? "application/octet-stream",
      "Last-Modified": modified.toUTCString(),
    });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(port, "127.0.0.1", () => resolve(server)));
}
const server = await serve(dist);
const base = `http://127.0.0.1:${server.address().port}/`;

// Chromium has been seen to crash at start-up (SIGSEGV before its first
// page) on a busy machine: a launch is tried up to three times.
async function launch() {
  for (let attempt = 1; ; attempt++) {
    try {
      return await chromium.launch({
        executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
        args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
      });
    } catch (e) {
      if (attempt >= 3) throw e;
      console.log(`Chromium did not start (attempt ${attempt}): ${String(e.message).split("\n")[0]}`);
      await new Promise((resolve) => setTimeout(resolve, 2000));
    }
  }
}
const browser = await launch();
const context = await browser.newContext({ viewport: size, acceptDownloads: true });

/** Opens `query` on a fresh page; every console error or page error fails the test. */
async function open(query, label) {
  const page = await context.newPage();
  page.on("console", (m) => {
    if (m.type() === "error") fail(`${label}: console error: ${m.text().slice(0, 400)}`);
  });
  page.on("pageerror", (e) => fail(`${label}: page error: ${e.message.slice(0, 400)}`));
  // Tasks that held the page's thread for 50 ms or more.
  await page.addInitScript(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.longTasks.push({ start: e.startTime, duration: e.duration });
    }).observe({ type: "longtask", buffered: true });
  });
  const start = Date.now();
  await page.goto(base + query);
  await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  // The first frame drawn after the explorer started.
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => resolve())));
  return { page, started: Date.now() - start };
}

/** Waits until the page has a result and nothing computes, then lets it draw. */
async function settle(page, timeout = 300_000) {
  await page.waitForFunction(() => !window.grainscope.busy() && window.grainscope.scalars_json() !== "", null, {
    timeout,
    polling: 100,
  });
  await page.waitForTimeout(600);
}

function decode(buffer) {
  return PNG.sync.read(buffer);
}

/** Whether the image shows more than one flat colour. */
function drawn(png) {
  const seen = new Set();
  for (let i = 0; i < png.data.length; i += 4 * 97) {
    seen.add((png.data[i] << 16) | (png.data[i + 1] << 8) | png.data[i + 2]);
    if (seen.size > 20) return true;
  }
  return false;
}

/** Screenshot `name`: kept under $OUT, checked drawn, compared with its reference. */
async function shot(page, name) {
  const buffer = await page.screenshot();
  fs.writeFileSync(path.join(out, `${name}.png`), buffer);
  const png = decode(buffer);
  if (!drawn(png)) fail(`${name}: the canvas is blank`);
  const reference = path.join(references, `${name}.png`);
  if (update) {
    fs.mkdirSync(references, { recursive: true });
    fs.writeFileSync(reference, buffer);
    ok(`${name}: reference written`);
    return png;
  }
  if (!fs.existsSync(reference)) {
    fail(`${name}: no reference ${reference} (UPDATE_REFERENCES=1 writes it)`);
    return png;
  }
  const want = decode(fs.readFileSync(reference));
  if (want.width !== png.width || want.height !== png.height) {
    fail(`${name}: ${png.width}×${png.height}, the reference is ${want.width}×${want.height}`);
    return png;
  }
  const diff = new PNG({ width: png.width, height: png.height });
  // Antialiasing and text hinting differ a little between runs; a changed
  // figure moves thousands of pixels.
  const differing = pixelmatch(png.data, want.data, diff.data, png.width, png.height, { threshold: 0.15 });
  const share = differing / (png.width * png.height);
  if (share > 0.004) {
    fs.writeFileSync(path.join(out, `${name}.diff.png`), PNG.sync.write(diff));
    fail(`${name}: ${(100 * share).toFixed(2)} % of the pixels differ from the reference (see ${name}.diff.png)`);
  } else {
    ok(`${name}: matches its reference (${(100 * share).toFixed(3)} % of pixels differ)`);
  }
  return png;
}

/** The native binary's scalars for a preset, when a binary was given. */
function native(preset, sets = []) {
  if (!binary) return null;
  const args = ["run", preset, "--json", ...sets.flatMap((s) => ["--set", s])];
  return JSON.parse(execFileSync(binary, args, { encoding: "utf8" }));
}

/** Compares the page's scalars with the native ones, to a relative `tolerance`. */
function same(label, web, want, tolerance, source = "the native binary's") {
  if (!want) return;
  const keys = Object.keys(want);
  const off = keys.filter((k) => {
    const a = web[k];
    const b = want[k];
    if (a === null || b === null) return a !== b;
    // A bound or an undefined value: the same status, bound and reason.
    if (typeof a === "object" || typeof b === "object") return JSON.stringify(a) !== JSON.stringify(b);
    return !(Math.abs(a - b) <= tolerance * Math.max(Math.abs(a), Math.abs(b)) || a === b);
  });
  if (off.length > 0 || Object.keys(web).length !== keys.length) {
    const text = (v) => (typeof v === "object" ? JSON.stringify(v) : v);
    fail(`${label}: scalars differ from the native binary: ${off.map((k) => `${k} ${text(web[k])} vs ${text(want[k])}`).join(", ")}`);
  } else {
    ok(`${label}: ${keys.length} scalars equal ${source} (relative ${tolerance})`);
  }
}

/** Where the top bar's "Open preset…" button is drawn at 1024×768. */
const OPEN_BUTTON = { x: 197, y: 14 };

/** Where the top bar's Link button is drawn at 1024×768. */
const LINK_BUTTON = { x: 222, y: 40 };

/** Milliseconds from loading the page to its first picture, per load. */
const firstPictures = [];

const scalars = async (page) => JSON.parse(await page.evaluate(() => window.grainscope.scalars_json()));

// BROWSER_ONLY=hall,phone runs only those parts (while working on them).
const only = process.env.BROWSER_ONLY ?? "";
try {
  if (only === "") await everything();
  if (only === "" || only.includes("hall")) await lectureHall();
  if (only === "" || only.includes("phone")) await phone();
} catch (e) {
  fail(`stopped: ${e.stack ?? e}`);
} finally {
  await browser.close();
  server.close();
}

/** Every check but the lecture hall's and the phone's. */
async function everything() {
  // 1. A collision by its link: first picture, reference, native numbers.
  {
    const { page, started } = await open("?preset=ice-bounce-8ms", "collision");
    firstPictures.push(started);
    await settle(page);
    await shot(page, "ice-bounce-8ms");
    // The browser's maths library may differ from the system's in the last bit.
    same("ice-bounce-8ms", await scalars(page), native("ice-bounce-8ms"), 1e-6);

    // 2. Drag the impact-velocity slider to its left: the spheres stick.
    const before = await scalars(page);
    const png = decode(await page.screenshot());
    await page.mouse.move(71, 444);
    await page.mouse.down();
    await page.mouse.move(50, 444, { steps: 5 });
    await page.mouse.move(30, 444, { steps: 5 });
    await page.mouse.up();
    // Away from the slider, so that no tooltip shows.
    await page.mouse.move(1010, 760);
    await settle(page);
    const after = await scalars(page);
    const moved = await shot(page, "ice-bounce-dragged");
    const changed = pixelmatch(png.data, moved.data, null, png.width, png.height, { threshold: 0.15 });
    if (after.e === before.e || changed < 2000) {
      fail(`slider drag: e ${before.e} → ${after.e}, ${changed} pixels changed`);
    } else {
      ok(`slider drag: e ${before.e.toFixed(3)} → ${after.e.toFixed(3)}, ${changed} pixels changed`);
    }

    // The Link button puts this state into the address: it reopens it.
    await page.mouse.click(LINK_BUTTON.x, LINK_BUTTON.y);
    await page.waitForFunction(() => location.search.startsWith("?scene="), null, { timeout: 10_000 }).catch(() => {});
    const query = await page.evaluate(() => location.search);
    // The Link card shows the address as a QR code a phone can read off the screen.
    await page.waitForTimeout(600);
    const card = decode(await page.screenshot({ path: path.join(out, "link-card.png") }));
    const scanned = jsQR(new Uint8ClampedArray(card.data), card.width, card.height);
    const address = await page.evaluate(() => location.href);
    if (scanned?.data !== address) {
      fail(`Link card: the QR code reads ${JSON.stringify(scanned?.data)}, the address is ${address}`);
    } else {
      ok(`Link card: its QR code reads ${address}`);
    }
    await page.keyboard.press("Escape");
    await page.waitForTimeout(300);
    if (!query.startsWith("?scene=hysteresis&") || !query.includes("velocity=")) {
      fail(`Link: the address reads ${JSON.stringify(query)}`);
    } else {
      const linked = (await open(query, "link")).page;
      await settle(linked);
      same(`the link ${query}`, await scalars(linked), after, 0, "the dragged state's");
      await linked.close();
    }

    // 3. Export the figure as PNG: a download that reopens this state.
    const [download] = await Promise.all([page.waitForEvent("download"), page.mouse.click(397, 700)]);
    const exported = path.join(out, download.suggestedFilename());
    await download.saveAs(exported);
    ok(`export downloaded as ${download.suggestedFilename()} (${fs.statSync(exported).size} bytes)`);
    await page.close();

    const fresh = (await open("?preset=ice-bounce-8ms", "reimport")).page;
    await settle(fresh);
    const bytes = fs.readFileSync(exported).toString("base64");
    await fresh.evaluate(
      ({ bytes, name }) => {
        const data = Uint8Array.from(atob(bytes), (c) => c.charCodeAt(0));
        const transfer = new DataTransfer();
        transfer.items.add(new File([data], name, { type: "image/png" }));
        const canvas = document.getElementById("explorer");
        for (const type of ["dragenter", "dragover", "drop"]) {
          canvas.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
        }
      },
      { bytes, name: download.suggestedFilename() },
    );
    await fresh.waitForFunction((e) => JSON.parse(window.grainscope.scalars_json() || "{}").e === e, after.e, {
      timeout: 30_000,
    }).then(
      () => ok(`the dropped PNG reopened its state (e = ${after.e.toFixed(3)})`),
      () => fail("the dropped PNG did not reopen its state"),
    );
    await fresh.close();
  }

  // 4. A disk map by its link: a heavy scene, computed in a Web Worker.
  {
    const { page } = await open("?preset=batch-fig-5-4", "disk map");
    const t0 = Date.now();
    await settle(page);
    ok(`disk map computed in a worker in ${Date.now() - t0} ms`);
    await shot(page, "batch-fig-5-4");
    same("batch-fig-5-4", await scalars(page), native("batch-fig-5-4"), 1e-6);

    // A click on the map inspects the batch under it: the model the worker
    // computed came with its result.
    const frame = await page.evaluate(() => Array.from(window.grainscope.plot_frame("disk-map")));
    if (frame.length !== 4) {
      fail("disk map: the map's axes were not drawn");
    } else {
      await page.mouse.click((frame[0] + frame[2]) / 2, (frame[1] + frame[3]) / 2);
      await page.waitForFunction(() => window.grainscope.inspection() !== "", null, { timeout: 10_000 }).catch(() => {});
      const title = await page.evaluate(() => window.grainscope.inspection());
      if (title === "") {
        fail("disk map: a click on the map inspected nothing");
      } else {
        ok(`disk map: a click on the map inspects "${title}"`);
        await page.mouse.move(1010, 760);
        await page.waitForTimeout(400);
        await page.screenshot({ path: path.join(out, "batch-fig-5-4-inspected.png") });
      }
    }
    await page.close();
  }

  // A longer heavy scene (the planetesimal formation zone of Fig. 5.9: 30
  // disks, each with 500 and 250 batches), shared among a worker per core:
  // the page's thread is never held while the workers compute, and the
  // whole computation, from the start of the page's job (its preview
  // included) to the result, is timed against the native binary's whole
  // process on the same machine. The aim is 1.5×; here, on two cores with
  // no GPU, it is about 1.55×: the WebAssembly batch model is slower than
  // native on one core (its logarithms and powers are Rust's libm), and
  // the frames drawn in software take the GPU process 50-250 ms of a core
  // each, so that the page, seeing SwiftShader, redraws every 2 s while
  // the workers compute (every 400 ms it took 2.1×). One worker alone
  // takes 3.6×: the check fails above 2.6×, where the workers no longer
  // share the disks. (The page's own thread is what the workers keep free.)
  {
    const { page } = await open("?preset=batch-fig-5-9", "formation zone");
    // This browser draws with SwiftShader: the page must know it.
    const redraw = await page.evaluate(() => window.grainscope.redraw_ms());
    if (redraw !== 2000) fail(`formation zone: the page redraws every ${redraw} ms while workers compute; drawing in software it should every 2000 ms`);
    const from = await page.evaluate(() => performance.now());
    const t0 = Date.now();
    let sawProgress = 0;
    while (await page.evaluate(() => window.grainscope.busy() || window.grainscope.scalars_json() === "")) {
      sawProgress = Math.max(sawProgress, await page.evaluate(() => window.grainscope.progress()));
      if (Date.now() - t0 > 300_000) break;
      await page.waitForTimeout(50);
    }
    const took = Date.now() - t0;
    const held = await page.evaluate((from) => window.longTasks.filter((t) => t.start > from), from);
    const longest = Math.max(0, ...held.map((t) => t.duration));
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    // The same page at rest, redrawn as the pointer moves over its plot: what
    // drawing alone costs on this machine.
    await page.waitForTimeout(600);
    const rest = await page.evaluate(() => performance.now());
    for (let i = 0; i < 25; i++) {
      await page.mouse.move(520 + 12 * i, 250 + 6 * i);
      await page.waitForTimeout(80);
    }
    const drawing = Math.max(
      0,
      ...(await page.evaluate((rest) => window.longTasks.filter((t) => t.start > rest), rest)).map((t) => t.duration),
    );
    // The issue's aim is 100 ms; the frame that first draws an arriving
    // preview takes 90-115 ms here (software GL, the other core busy with
    // a worker). Anything longer means work crept onto the page's thread.
    const allowed = Math.max(150, drawing + 25);
    let line =
      `formation zone (Fig. 5.9) computed in ${took} ms by the workers of ${cores} cores (the page redrawing every ${redraw} ms), progress seen up to ` +
      `${(100 * sawProgress).toFixed(0)} %; longest task on the page's thread meanwhile ${longest.toFixed(0)} ms ` +
      `(drawing alone, at rest: ${drawing.toFixed(0)} ms)`;
    if (longest > allowed) {
      fail(`formation zone: the page's thread was held for ${longest.toFixed(0)} ms while the workers computed (allowed ${allowed.toFixed(0)} ms)`);
    }
    if (sawProgress <= 0) fail("formation zone: no progress reported while the workers computed");
    if (binary) {
      const t1 = process.hrtime.bigint();
      const want = native("batch-fig-5-9");
      const desktop = Number(process.hrtime.bigint() - t1) / 1e6;
      const ratio = took / desktop;
      line += `; ${desktop.toFixed(0)} ms on the desktop (whole process, every core): ${ratio.toFixed(2)}× (aim 1.5×)`;
      console.log(`budget: ${line}`);
      if (ratio > 2.6) fail(`formation zone: ${ratio.toFixed(2)}× the desktop's time in the browser (budget 2.6×: are the disks shared among the workers?)`);
      same("formation-zone", await scalars(page), want, 1e-6);
    } else {
      ok(line);
    }
    await page.mouse.move(1010, 760);
    await page.waitForTimeout(800);
    await shot(page, "formation-zone");
    await page.close();
  }

  // 5. A deck slide by its link, presented.
  {
    const { page } = await open("?deck=porous-growth&slide=3", "deck");
    await settle(page);
    await shot(page, "porous-growth-03");
    // A clicker's Shift+F5 resumes the show at the slide left and F5 starts
    // it from the first, instead of reloading the page.
    await page.evaluate(() => { window.notReloaded = true; });
    const status = () => page.evaluate(() => window.grainscope.status());
    await page.keyboard.press("Escape");
    await page.waitForTimeout(800);
    const left = await status();
    await page.keyboard.press("Shift+F5");
    await page.waitForTimeout(1500);
    const resumed = await status();
    await page.keyboard.press("F5");
    await page.waitForTimeout(1500);
    const started = await status();
    const kept = await page.evaluate(() => window.notReloaded === true);
    if (!kept || !left.startsWith("left the deck") || !resumed.startsWith("slide 3:") || !started.startsWith("slide 1:")) {
      fail(`F5: the page ${kept ? "stayed" : "reloaded"}; Esc: "${left}", Shift+F5: "${resumed}", F5: "${started}"`);
    } else {
      ok(`F5 and Shift+F5 start and resume the show without reloading the page ("${started}")`);
    }
    await page.close();
  }

  // The command palette (F2): typing "lecture" and Enter turns lecture mode
  // on, which gives the plot most of the page. On a page of its own storage
  // (the deck above leaves its session).
  {
    const own = await browser.newContext({ viewport: size });
    const page = await own.newPage();
    page.on("pageerror", (e) => fail(`palette: page error: ${e.message.slice(0, 400)}`));
    page.on("console", (m) => {
      if (m.type() === "error") fail(`palette: console error: ${m.text().slice(0, 400)}`);
    });
    await page.goto(base + "?preset=ice-bounce-8ms");
    await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
    await settle(page);
    const frame = async () => Array.from(await page.evaluate(() => window.grainscope.plot_frame("contact-radius")));
    const area = (f) => (f.length === 4 ? (f[2] - f[0]) * (f[3] - f[1]) : 0);
    const before = area(await frame());
    await page.mouse.click(700, 400);
    // Waits of a few frames between the keys, for a busy machine.
    await page.keyboard.press("F2");
    await page.waitForTimeout(800);
    await page.keyboard.type("lecture", { delay: 30 });
    await page.waitForTimeout(500);
    await page.keyboard.press("Enter");
    await page.waitForTimeout(1500);
    const after = area(await frame());
    if (!(before > 0 && after > 1.3 * before)) {
      fail(`palette: F2, "lecture", Enter left the plot at ${Math.round(after)} px² (before ${Math.round(before)})`);
    } else {
      ok(`palette: F2, "lecture", Enter: lecture mode, the plot ${(after / before).toFixed(2)}× larger`);
    }
    fs.writeFileSync(path.join(out, "palette-lecture.png"), await page.screenshot());
    await own.close();
  }

  // A movie in the browser is one download: an animated PNG of every figure
  // (the palette's "Movie" on a played collision).
  {
    const own = await browser.newContext({ viewport: size, acceptDownloads: true });
    const page = await own.newPage();
    page.on("pageerror", (e) => fail(`movie: page error: ${e.message.slice(0, 400)}`));
    page.on("console", (m) => {
      if (m.type() === "error") fail(`movie: console error: ${m.text().slice(0, 400)}`);
    });
    const downloads = [];
    page.on("download", (d) => downloads.push(d));
    await page.goto(base + "?preset=ice-bounce-8ms");
    await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
    await settle(page);
    await page.mouse.click(700, 400);
    await page.keyboard.press("F2");
    await page.waitForTimeout(800);
    await page.keyboard.type("Movie", { delay: 30 });
    await page.waitForTimeout(500);
    await page.keyboard.press("Enter");
    const deadline = Date.now() + 180_000;
    while (downloads.length === 0 && Date.now() < deadline) await page.waitForTimeout(500);
    await page.waitForTimeout(3000);
    const files = await Promise.all(downloads.map(async (d) => [d.suggestedFilename(), fs.readFileSync(await d.path())]));
    const animated = files.length === 1 && files[0][1].includes(Buffer.from("acTL"));
    if (!animated) {
      fail(`movie: ${files.length} download(s) (${files.map((f) => f[0]).join(", ")}), expected one animated PNG`);
    } else {
      fs.writeFileSync(path.join(out, files[0][0]), files[0][1]);
      ok(`movie: one download, ${files[0][0]}, an animated PNG of ${(files[0][1].length / 1e6).toFixed(1)} MB`);
    }
    await own.close();
  }

  // A preset opened with the file picker (the top bar's "Open preset…"), on
  // a page of its own storage (the pages above leave a deck's session).
  {
    const own = await browser.newContext({ viewport: size });
    const page = await own.newPage();
    page.on("pageerror", (e) => fail(`file picker: page error: ${e.message.slice(0, 400)}`));
    await page.goto(base + "?preset=ice-bounce-8ms");
    await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
    await settle(page);
    // The pointer rests on the button for a frame before the click, as a
    // user's would; a click that a busy frame missed is tried again.
    let chooser = null;
    for (let attempt = 0; attempt < 5 && chooser === null; attempt++) {
      await page.mouse.move(OPEN_BUTTON.x, OPEN_BUTTON.y);
      await page.waitForTimeout(300 + 200 * attempt);
      [chooser] = await Promise.all([
        page.waitForEvent("filechooser", { timeout: 15_000 }).catch(() => null),
        page.mouse.click(OPEN_BUTTON.x, OPEN_BUTTON.y),
      ]);
    }
    if (chooser === null) {
      await page.screenshot({ path: path.join(out, "file-picker-failed.png") });
      throw new Error(`no file picker opened (status: ${await page.evaluate(() => window.grainscope.status())})`);
    }
    await chooser.setFiles(path.join(here, "..", "..", "presets", "ice-stick-2ms.ron"));
    await page
      .waitForFunction(() => window.grainscope.status().includes("ice-stick-2ms"), null, { timeout: 20_000 })
      .then(
        async () => {
          await settle(page);
          same("ice-stick-2ms.ron from the file picker", await scalars(page), native("ice-stick-2ms"), 1e-6);
        },
        async () => fail(`file picker: the picked preset did not open (status: ${await page.evaluate(() => window.grainscope.status())})`),
      );
    await own.close();
  }

  // An unreadable session in the browser's storage: a fresh start with a
  // message, the old text set aside, never a blank page.
  {
    const broken = await browser.newContext({ viewport: size });
    await broken.addInitScript(() => {
      if (localStorage.getItem("grainscope-session-unreadable") === null) {
        localStorage.setItem("grainscope-session", "(scene: \"hysteresis\", broken");
      }
    });
    const page = await broken.newPage();
    page.on("pageerror", (e) => fail(`unreadable session: page error: ${e.message.slice(0, 400)}`));
    await page.goto(base);
    await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
    await settle(page);
    const status = await page.evaluate(() => window.grainscope.notices());
    const aside = await page.evaluate(() => localStorage.getItem("grainscope-session-unreadable"));
    const picture = decode(await page.screenshot({ path: path.join(out, "unreadable-session.png") }));
    if (!status.includes("could not be read") || aside === null || !drawn(picture)) {
      fail(`unreadable session: notice ${JSON.stringify(status)}, set aside: ${aside !== null}, drawn: ${drawn(picture)}`);
    } else {
      ok(`unreadable session: a fresh start that says so ("${status.slice(0, 90)}…"), the old text set aside`);
    }
    await broken.close();
  }

  // Budget: the restitution scene from cold, on the page against the desktop.
  {
    const { page, started } = await open("", "timing");
    firstPictures.push(started);
    const again = await open("?preset=restitution-ice", "timing");
    firstPictures.push(again.started);
    await again.page.close();
    // The first load compiles the module; a machine this busy varies by a second.
    const best = Math.min(...firstPictures);
    console.log(`budget: from loading the page to its first picture ${firstPictures.join(", ")} ms (best ${best} ms)`);
    if (best > 3000) fail(`the first picture took at least ${best} ms (budget 3 s)`);
    const web = [];
    for (let i = 0; i < 3; i++) web.push(await page.evaluate(() => window.grainscope.time_preset("restitution-ice")));
    await page.close();
    let line = `budget: restitution-ice from cold ${Math.min(...web).toFixed(0)} ms in the browser`;
    if (binary) {
      const desktop = [];
      for (let i = 0; i < 3; i++) {
        const t0 = process.hrtime.bigint();
        execFileSync(binary, ["run", "restitution-ice", "--json"], { env: { ...process.env, RAYON_NUM_THREADS: "1" } });
        desktop.push(Number(process.hrtime.bigint() - t0) / 1e6);
      }
      const ratio = Math.min(...web) / Math.min(...desktop);
      line += `, ${Math.min(...desktop).toFixed(0)} ms on the desktop (one thread, whole process): ${ratio.toFixed(2)}×`;
      if (ratio > 3) fail(`restitution-ice is ${ratio.toFixed(2)}× slower in the browser (budget 3×)`);
    }
    console.log(line);
  }

  // Budgets: the module's size.
  const wasm = "grainscope_bg.wasm";
  const raw = fs.statSync(path.join(dist, wasm)).size;
  const gz = fs.statSync(path.join(dist, wasm + ".gz")).size;
  console.log(`budget: ${wasm} ${(raw / 1e6).toFixed(2)} MB raw, ${(gz / 1e6).toFixed(2)} MB as the page loads it (gzip)`);
  if (raw > 9e6 || gz > 4e6) fail(`the module is over budget (9 MB raw, 4 MB gzip)`);
  if (!zlib.gunzipSync(fs.readFileSync(path.join(dist, wasm + ".gz"))).equals(fs.readFileSync(path.join(dist, wasm)))) {
    fail(`${wasm}.gz is not ${wasm} gzipped`);
  }

}

/**
 * The lecture hall: a student's first visit at 5 Mbit/s (bytes downloaded,
 * time to the first picture); then, with the server gone and the browser
 * offline, a reload and a fresh link (a QR scan) start from the service
 * worker's files; a new version on the server replaces them on the next
 * online visit. On a copy of web/dist served from a port of its own (an
 * origin of its own for the service worker).
 */
async function lectureHall() {
  const root = fs.mkdtempSync(path.join(out, "hall-"));
  for (const f of fs.readdirSync(dist)) fs.copyFileSync(path.join(dist, f), path.join(root, f));
  const hallServer = await serve(root);
  const port = hallServer.address().port;
  const hallBase = `http://127.0.0.1:${port}/`;
  const hall = await browser.newContext({ viewport: size });
  const page = await hall.newPage();
  page.on("pageerror", (e) => fail(`lecture hall: page error: ${e.message.slice(0, 400)}`));
  page.on("console", (m) => {
    if (m.type() === "error") fail(`lecture hall: console error: ${m.text().slice(0, 400)}`);
  });
  const cdp = await hall.newCDPSession(page);
  await cdp.send("Network.enable");
  const mbit = 5;
  await cdp.send("Network.emulateNetworkConditions", {
    offline: false,
    latency: 40,
    downloadThroughput: (mbit * 1e6) / 8,
    uploadThroughput: 1e6 / 8,
  });
  let bytes = 0;
  cdp.on("Network.loadingFinished", (e) => (bytes += e.encodedDataLength));
  const start = Date.now();
  await page.goto(hallBase + "?preset=restitution-ice", { waitUntil: "commit" });
  await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => resolve())));
  const first = Date.now() - start;
  await settle(page);
  const downloaded = bytes;
  console.log(
    `budget: a student's first visit at ${mbit} Mbit/s: ${(downloaded / 1e6).toFixed(2)} MB downloaded, the first picture after ${(first / 1000).toFixed(1)} s`,
  );
  if (downloaded > 4e6) fail(`a student downloads ${(downloaded / 1e6).toFixed(2)} MB (budget 4 MB)`);
  if (first > 8000) fail(`at ${mbit} Mbit/s the first picture took ${(first / 1000).toFixed(1)} s (budget 8 s)`);
  await cdp.send("Network.emulateNetworkConditions", { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  await cdp.detach();
  // The service worker controls the page once it has kept every file.
  const version = async (p) =>
    p.evaluate(async () => (await caches.keys()).filter((k) => k.startsWith("grainscope ")).join(" | "));
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 60_000 });
  const kept = await version(page);

  // No network: the server is gone and the browser offline.
  const close = (s) => new Promise((resolve) => (s.closeAllConnections(), s.close(resolve)));
  await close(hallServer);
  await hall.setOffline(true);
  const offline = [];
  await page.reload();
  await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  await settle(page);
  const reloaded = decode(await page.screenshot({ path: path.join(out, "offline-reload.png") }));
  if (!drawn(reloaded)) offline.push("the reloaded page is blank");
  const scan = await hall.newPage();
  scan.on("pageerror", (e) => fail(`lecture hall: page error: ${e.message.slice(0, 400)}`));
  await scan.goto(hallBase + "?preset=ice-bounce-8ms");
  await scan.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  await settle(scan);
  fs.writeFileSync(path.join(out, "offline-link.png"), await scan.screenshot());
  if (binary) same("ice-bounce-8ms opened offline from a link", await scalars(scan), native("ice-bounce-8ms"), 1e-6);
  await scan.close();
  if (offline.length > 0) fail(`offline: ${offline.join("; ")}`);
  else ok(`offline (server gone, browser offline): a reload and a fresh link start from the kept files (${kept})`);

  // A new version on the server (the build writes a new hash into sw.js)
  // replaces the kept one on the next online visit, and is used from the
  // load after it.
  fs.writeFileSync(
    path.join(root, "index.html"),
    fs.readFileSync(path.join(root, "index.html"), "utf8").replace("<head>", '<head>\n  <meta name="grainscope-version" content="next">'),
  );
  fs.writeFileSync(path.join(root, "sw.js"), fs.readFileSync(path.join(root, "sw.js"), "utf8").replace(/const VERSION = "([^"]*)"/, 'const VERSION = "$1-next"'));
  // The same origin: the same port.
  const again = await serve(root, port);
  await hall.setOffline(false);
  await page.reload();
  await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  // The browser checks sw.js after the load; the new files are kept in the background.
  for (let waited = 0; waited < 60_000; waited += 500) {
    const now = await version(page);
    if (now.endsWith("-next") && !now.includes("|")) break;
    await page.waitForTimeout(500);
  }
  const replaced = await version(page);
  await page.reload();
  await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
  const marked = await page.evaluate(() => document.querySelector('meta[name="grainscope-version"]')?.content ?? "");
  if (!replaced.endsWith("-next") || replaced.includes("|") || marked !== "next") {
    fail(`a new version: kept "${replaced}", the page after it "${marked}"`);
  } else {
    ok(`a new version replaces the kept files on the next online visit ("${replaced}") and runs from the load after it`);
  }
  await hall.close();
  await close(again);
  fs.rmSync(root, { recursive: true, force: true });
}

/**
 * A student's phone, portrait and landscape, with touch: the figure takes
 * the width; a tap opens the parameters drawer, a tap on a slider changes
 * the result, a swipe scrolls the drawer; the Link card fits and its QR
 * code reads; a deck and a link open. No console error, and no complaint
 * about touch events, anywhere. Positions are those of the layout at these
 * sizes (the same as the desktop window's at the same size).
 */
async function phone() {
  const sizes = [
    ["portrait", { width: 390, height: 844 }],
    ["landscape", { width: 844, height: 390 }],
  ];
  for (const [name, viewport] of sizes) {
    const own = await browser.newContext({ viewport, hasTouch: true, isMobile: true });
    const page = await own.newPage();
    const problems = [];
    page.on("pageerror", (e) => problems.push(`page error: ${e.message.slice(0, 300)}`));
    page.on("console", (m) => {
      if (m.type() === "error" || /preventDefault|passive/i.test(m.text())) problems.push(`console ${m.type()}: ${m.text().slice(0, 300)}`);
    });
    await page.goto(base + "?preset=ice-bounce-8ms");
    await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
    await settle(page);
    const frame = Array.from(await page.evaluate(() => window.grainscope.plot_frame("contact-radius")));
    const share = frame.length === 4 ? (frame[2] - frame[0]) / viewport.width : 0;
    fs.writeFileSync(path.join(out, `phone-${name}.png`), await page.screenshot());
    // The plot's frame (inside its axes and legend) across most of the width.
    const wide = name === "portrait" ? 0.7 : 0.6;
    if (!(share > wide) || frame[2] > viewport.width) {
      problems.push(`the figure's frame spans ${frame.map((v) => v.toFixed(0)).join(", ")} of ${viewport.width} px`);
    }
    const before = await scalars(page);
    // The drawer: a tap on "Parameters".
    const cdp = await own.newCDPSession(page);
    const tap = async (x, y) => {
      await page.touchscreen.tap(x, y);
      await page.waitForTimeout(500);
    };
    const swipe = async (x, y0, y1) => {
      const point = (y) => [{ x, y, id: 1 }];
      await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: point(y0) });
      for (let k = 1; k <= 8; k++) {
        await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: point(y0 + ((y1 - y0) * k) / 8) });
        await page.waitForTimeout(30);
      }
      await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
      await page.waitForTimeout(600);
    };
    await tap(45, 15);
    const drawer = await page.screenshot({ path: path.join(out, `phone-${name}-drawer.png`) });
    if (name === "portrait") {
      // The impact velocity's slider (8 m/s) near its right end: a faster collision.
      await tap(100, 513);
      await settle(page);
      const after = await scalars(page);
      if (!(Math.abs(after.e - before.e) > 0.01)) problems.push(`a tap on the velocity slider moved e from ${before.e} to ${after.e}`);
    }
    // A swipe up scrolls the drawer.
    await swipe(250, viewport.height - 60, 120);
    const swiped = await page.screenshot({ path: path.join(out, `phone-${name}-swiped.png`) });
    const a = decode(drawer);
    const b = decode(swiped);
    const moved = pixelmatch(a.data, b.data, null, a.width, a.height, { threshold: 0.15 });
    if (moved < 1000) problems.push(`a swipe over the drawer moved ${moved} pixels`);
    const selected = await page.evaluate(() => String(window.getSelection?.() ?? ""));
    if (selected !== "") problems.push(`a swipe selected text: ${JSON.stringify(selected.slice(0, 60))}`);
    await tap(45, 15);
    // The Link card (the palette's "Link" by keyboard): it fits, its code reads.
    await page.keyboard.press("F2");
    await page.waitForTimeout(600);
    await page.keyboard.type("link", { delay: 30 });
    await page.waitForTimeout(400);
    await page.keyboard.press("Enter");
    await page.waitForTimeout(1000);
    const card = decode(await page.screenshot({ path: path.join(out, `phone-${name}-link.png`) }));
    const scanned = jsQR(new Uint8ClampedArray(card.data), card.width, card.height);
    const address = await page.evaluate(() => location.href);
    if (scanned?.data !== address) problems.push(`the Link card's code reads ${JSON.stringify(scanned?.data)}, not ${address}`);
    await page.keyboard.press("Escape");
    // A deck's slide and a Monte Carlo link open here too.
    for (const query of ["?deck=porous-growth&slide=2", "?scene=restitution&velocity=4"]) {
      await page.goto(base + query);
      await page.waitForFunction(() => typeof window.grainscope?.busy === "function", null, { timeout: 60_000 });
      await settle(page);
      const label = query.replace(/[?&=]/g, "-").replace(/^-/, "");
      const png = decode(await page.screenshot({ path: path.join(out, `phone-${name}-${label}.png`) }));
      if (!drawn(png)) problems.push(`${query} is blank`);
    }
    if (problems.length > 0) fail(`phone ${name} ${viewport.width}×${viewport.height}: ${problems.join("; ")}`);
    else ok(`phone ${name} ${viewport.width}×${viewport.height} with touch: the figure ${(100 * share).toFixed(0)} % of the width, the drawer, a slider tap, a swipe, the Link card, a deck and a link`);
    await own.close();
  }
}

if (failures.length > 0) {
  console.log(`${failures.length} browser check(s) failed; screenshots in ${out}`);
  process.exit(1);
}
console.log(`every browser check passed; screenshots in ${out}`);
