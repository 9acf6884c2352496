#!/usr/bin/env bash
# Builds the browser version of grainscope into web/dist: index.html, the
# WebAssembly module and its JavaScript loader. Copy web/dist onto any static
# web server, or serve it here with
#     python3 -m http.server -d web/dist 8000
# and open http://127.0.0.1:8000 (add ?preset=ice-bounce-8ms or
# ?deck=porous-growth&slide=3 to open a preset or a deck's slide).
set -euo pipefail
cd "$(dirname "$0")/.."
target="${CARGO_TARGET_DIR:-target}"
# The cargo profile: `web` (Cargo.toml: link-time optimised, smaller), or
# `release` for a quicker build while working on the page.
profile="${GRAINSCOPE_WEB_PROFILE:-web}"

# The bindings' tool, web/bindgen: wasm-bindgen's library at the exact
# version of the `wasm-bindgen` crate in Cargo.lock (its own lock file pins
# it; the two must agree). It compiles in about a minute, a third of what
# `cargo install wasm-bindgen-cli` takes, since it leaves out the command's
# test runner, and it is built once per cargo target.
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
tool_version=$(awk '/^name = "wasm-bindgen-cli-support"$/ { getline; gsub(/"/, "", $3); print $3; exit }' web/bindgen/Cargo.lock)
if [ "$version" != "$tool_version" ]; then
    echo "web/bindgen uses wasm-bindgen-cli-support $tool_version, but the page links wasm-bindgen $version:" \
        "set web/bindgen/Cargo.toml to =$version and run \`cargo update --manifest-path web/bindgen/Cargo.toml\`" >&2
    exit 1
fi
echo "== the bindings' tool (web/bindgen, wasm-bindgen $version)"
CARGO_TARGET_DIR="$target" cargo build --release --locked --manifest-path web/bindgen/Cargo.toml
bindgen="$target/release/grainscope-bindgen"
if command -v rustup >/dev/null; then
    rustup target add wasm32-unknown-unknown >/dev/null
fi

echo "== building the WebAssembly module"
# With WebAssembly's 128-bit vectors (simd128: Chrome and Firefox since 2021,
# Safari since 16.4, 2023): the compiler pairs the model's independent
# floating-point operations, the same IEEE operations, so the same numbers.
# Fig. 5.9's formation zone computes about 6 % faster, and the module is
# 0.5 MB smaller. Only this build sets it: `.ci/run`'s `cargo check` for
# wasm32 checks and lints the same code without it.
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="${CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS:--C target-feature=+simd128}"
cargo build -p grainscope-web --profile "$profile" --target wasm32-unknown-unknown

echo "== web/dist"
staging=$(mktemp -d web/dist.XXXXXX)
trap 'rm -rf "$staging"' EXIT
"$bindgen" "$target/wasm32-unknown-unknown/$profile/grainscope_web.wasm" "$staging"
# Binaryen's optimiser (npm package `binaryen`, pinned in web/package-lock.json;
# Debian's binaryen is too old for this module), for speed (-O2): the module
# is 11 % smaller than the compiler's (8.83 against 9.96 MB). For speed, -O3
# computed Fig. 5.9's formation zone 6 % faster than -Oz did (14.5 s against
# 15.3 s, headless Chromium on two cores), and -O2 as fast as -O3 (four runs
# of each in turn), in 112 s of one core against -O3's 246 s, which a cold
# run of .ci/run spends beside the tests' compiles. It takes minutes, so its
# output is kept per input.
if [ ! -x web/node_modules/.bin/wasm-opt ] && command -v npm >/dev/null; then
    (cd web && npm ci --no-audit --no-fund --loglevel=error)
fi
if [ -x web/node_modules/.bin/wasm-opt ]; then
    options=(-O2 --enable-simd --enable-bulk-memory --enable-sign-ext --enable-mutable-globals
        --enable-nontrapping-float-to-int --enable-reference-types --enable-multivalue)
    # Kept by the module and the options together.
    kept="$target/web-opt/$( (cat "$staging/grainscope_bg.wasm"; echo "${options[*]}") | sha256sum | cut -c1-24).wasm"
    if [ ! -f "$kept" ]; then
        echo "== wasm-opt ${options[0]} (about two minutes)"
        mkdir -p "$target/web-opt"
        web/node_modules/.bin/wasm-opt "${options[@]}" "$staging/grainscope_bg.wasm" -o "$kept.tmp"
        mv "$kept.tmp" "$kept"
    fi
    cp "$kept" "$staging/grainscope_bg.wasm"
else
    echo "(no npm: the module is not optimised by binaryen and is about 13 % larger)" >&2
fi
cp web/index.html web/worker.js "$staging/"
# The page loads the module gzipped and unpacks it itself (index.html), so
# that any static server sends a third of its bytes; the plain module stays
# for browsers without DecompressionStream.
gzip -9 -n -c "$staging/grainscope_bg.wasm" >"$staging/grainscope_bg.wasm.gz"
# The service worker keeps the files of this version, named by their hash.
version=$(cat "$staging"/index.html "$staging"/grainscope.js "$staging"/grainscope_bg.wasm.gz "$staging"/worker.js |
    sha256sum | cut -c1-16)
sed "s/@VERSION@/$version/" web/sw.js >"$staging/sw.js"
chmod 755 "$staging"
rm -rf web/dist
mv "$staging" web/dist
trap - EXIT
ls -l web/dist
