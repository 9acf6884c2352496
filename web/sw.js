// The service worker of grainscope's page: after the first visit the page
// starts with no network. It keeps one version's files, named by a hash of
// them that web/build.sh writes below; a page loaded online makes the
// browser compare this file with the server's, and a new version's files
// are fetched in the background and used from the next load on (the old
// version's are then deleted).
const VERSION = "@VERSION@";
const FILES = ["./", "./index.html", "./grainscope.js", "./grainscope_bg.wasm.gz", "./worker.js"];
const PREFIX = `grainscope ${self.registration.scope} `;
const CACHE = PREFIX + VERSION;

self.addEventListener("install", (event) => {
  // "no-cache": revalidated with the server, so a file the page has just
  // downloaded is not downloaded again, and a changed one is.
  event.waitUntil(
    caches
      .open(CACHE)
      .then((cache) => cache.addAll(FILES.map((file) => new Request(file, { cache: "no-cache" }))))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith(PREFIX) && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) return;
  // A link's query (?preset=…, ?deck=…) is read by the page: every address
  // of a file is that file.
  event.respondWith(
    caches
      .open(CACHE)
      .then((cache) => cache.match(request, { ignoreSearch: true }))
      .then((kept) => kept ?? fetch(request)),
  );
});
