// A Web Worker of grainscope: the page sends ["module", compiled module]
// once, then ["job", bytes, parts] for each computation (parts: the bytes of
// its share of a computation several workers share, or null); the module posts
// progress, intermediate results and the result back (src/worker.rs).
import init, { run_job } from "./grainscope.js";

let ready = null;
self.onmessage = async (event) => {
  const [kind, payload] = event.data;
  if (kind === "module") {
    ready = init({ module_or_path: payload });
    return;
  }
  await ready;
  run_job(payload, event.data[2] ?? undefined);
};
