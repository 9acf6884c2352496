#!/usr/bin/env bash
# Builds grainscope's release artifacts into OUT (default ci-output/release),
# for users without a Rust toolchain:
#   grainscope-VERSION-x86_64-linux.tar.gz  the binary, presets and decks, README,
#       licence, citation, a desktop entry, an icon and install.sh; INSTALL.txt
#       names the oldest glibc the binary runs on
#   grainscope-VERSION-x86_64-windows.zip   the same for Windows 10 and later,
#       cross-built with mingw-w64
#   grainscope-VERSION-cp39-abi3-manylinux2014_x86_64.manylinux_2_17_x86_64.whl  the Python module for
#       every CPython ≥ 3.9 on Linux x86_64 (glibc ≥ 2.17), built with maturin and
#       zig as the linker
# and checks that the sources build for macOS on Apple silicon
# (aarch64-apple-darwin: `cargo check`; there is no macOS linker here).
# It installs what it lacks: Debian's mingw-w64, rustup's targets, and maturin
# and ziglang from PyPI (into a virtual environment of its own).
# `.ci/test-artifacts.sh OUT` then runs each of them.
# Usage: .ci/package.sh [OUT]
#   GRAINSCOPE_WINDOWS_TARGET: the cargo target of the Windows build (default
#   CARGO_TARGET_DIR), so that it can be built beforehand in a directory of
#   its own while other builds use CARGO_TARGET_DIR:
#     .ci/package.sh --prepare-windows   installs what the Windows build needs
#     .ci/package.sh --build-windows     builds grainscope.exe and nothing else
#   and so that the macOS check and the wheel can run beforehand, while
#   another step leaves a core idle:
#     .ci/package.sh --macos-and-wheel [OUT]   the macOS check, then the wheel into OUT
#     .ci/package.sh --archives [OUT]          the two archives alone
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/grainscope-target}"
windows_target="${GRAINSCOPE_WINDOWS_TARGET:-$CARGO_TARGET_DIR}"

# What the Windows build needs: Debian's mingw-w64 (and zip for its archive),
# rustup's target.
prepare_windows() {
    if ! command -v x86_64-w64-mingw32-gcc >/dev/null || ! command -v zip >/dev/null; then
        apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gcc-mingw-w64-x86-64 zip >/dev/null
    fi
    rustup target add x86_64-pc-windows-gnu >/dev/null
}
build_windows() {
    CARGO_TARGET_DIR="$windows_target" CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER=x86_64-w64-mingw32-gcc \
        cargo build --release --target x86_64-pc-windows-gnu --bin grainscope
}
# What this run makes: both archives, and the macOS check and the wheel.
archives=1
macos_and_wheel=1
case "${1:-}" in
    --prepare-windows)
        prepare_windows
        exit 0
        ;;
    --build-windows)
        build_windows
        exit 0
        ;;
    --macos-and-wheel)
        archives=0
        shift
        ;;
    --archives)
        macos_and_wheel=0
        shift
        ;;
esac
out=$(realpath -m "${1:-ci-output/release}")
version=$(awk -F'"' '/^version = / { print $2; exit }' Cargo.toml)
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
# Every file in the archives carries the commit's time, so that the same
# sources give the same archives.
epoch=$(git log -1 --format=%ct 2>/dev/null || echo 0)
mkdir -p "$out"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT

# The files both archives share.
common() {
    local dir=$1
    mkdir -p "$dir/presets/decks"
    cp presets/*.ron "$dir/presets/"
    cp presets/decks/*.ron "$dir/presets/decks/"
    cp README.md LICENSE CITATION.cff "$dir/"
}

# A reproducible archive of directory $2 (inside $1) as file $3.
pack_tar() {
    find "$1/$2" -exec touch -h -d "@$epoch" {} +
    tar --sort=name --owner=0 --group=0 --numeric-owner --mtime="@$epoch" -C "$1" -cf - "$2" | gzip -n -9 >"$3.tmp"
    mv "$3.tmp" "$3"
}
pack_zip() {
    find "$1/$2" -exec touch -h -d "@$epoch" {} +
    rm -f "$3.tmp"
    (cd "$1" && find "$2" -print | LC_ALL=C sort | zip -X -q -9 "$3.tmp" -@)
    mv "$3.tmp" "$3"
}

# The macOS check and the wheel: builds only, which share nothing with the
# archives (maturin's zig linker enters every crate's fingerprint).
macos_and_wheel() {
    echo "== macOS on Apple silicon: cargo check"
    rustup target add aarch64-apple-darwin >/dev/null
    cargo check --release --target aarch64-apple-darwin --bin grainscope

    echo "== the Python wheel (maturin, zig as the linker)"
    local venv="$HOME/.cache/grainscope-build-venv"
    if [ ! -x "$venv/bin/maturin" ] || ! "$venv/bin/python" -c "import ziglang" 2>/dev/null; then
        python3 -m venv "$venv"
        "$venv/bin/pip" install -q "maturin>=1.9,<2" "ziglang>=0.13,<0.16"
    fi
    rm -f "$out"/grainscope-*.whl
    PATH="$venv/bin:$PATH" maturin build --release --zig --compatibility manylinux2014 \
        --manifest-path python/Cargo.toml --out "$out" --quiet
}
if [ "$archives" = 0 ]; then
    macos_and_wheel
    ls -l "$out"
    exit 0
fi

echo "== Linux x86_64"
cargo build --release --bin grainscope
name="grainscope-$version-x86_64-linux"
dir="$stage/$name"
common "$dir"
install -m 755 "$CARGO_TARGET_DIR/release/grainscope" "$dir/grainscope"
strip "$dir/grainscope"
install -D -m 644 assets/desktop/grainscope.desktop "$dir/share/applications/grainscope.desktop"
install -D -m 644 assets/desktop/grainscope.svg "$dir/share/icons/hicolor/scalable/apps/grainscope.svg"
install -m 755 assets/desktop/install.sh "$dir/install.sh"
# The newest glibc symbol version the binary asks for is the oldest glibc it runs on.
glibc=$(objdump -T "$dir/grainscope" | grep -oE 'GLIBC_[0-9]+(\.[0-9]+)+' | sed 's/GLIBC_//' | sort -uV | tail -n 1)
cat >"$dir/INSTALL.txt" <<EOF
grainscope $version for Linux on x86_64 (commit $commit)

It runs on Linux with glibc $glibc or newer (\`ldd --version\` tells yours).
The window needs OpenGL (Mesa or a GPU driver) and X11 or Wayland, as
every Linux desktop has; the command line needs nothing else.

Run it where it is:
    ./grainscope                          the explorer window
    ./grainscope run ice-bounce-8ms       a preset without the window
    ./grainscope --help                   every command

Or install it for yourself (the command, a menu entry and its icon under
~/.local; PREFIX=... for another place; ./install.sh --uninstall removes them):
    ./install.sh

The shipped presets are built into the program; presets/ holds them as
files to copy and edit (\`./grainscope gui presets/restitution-ice.ron\`).
EOF
pack_tar "$stage" "$name" "$out/$name.tar.gz"
echo "$name.tar.gz: glibc >= $glibc"

echo "== Windows x86_64 (mingw-w64)"
prepare_windows
build_windows
name="grainscope-$version-x86_64-windows"
dir="$stage/$name"
common "$dir"
install -m 755 "$windows_target/x86_64-pc-windows-gnu/release/grainscope.exe" "$dir/grainscope.exe"
x86_64-w64-mingw32-strip "$dir/grainscope.exe"
# The DLLs it needs are all part of Windows: no MinGW runtime beside it.
if x86_64-w64-mingw32-objdump -p "$dir/grainscope.exe" | grep -iE 'DLL Name: (libgcc|libwinpthread|libstdc)'; then
    echo "grainscope.exe needs a MinGW runtime DLL" >&2
    exit 1
fi
cat >"$dir/INSTALL.txt" <<EOF
grainscope $version for Windows 10 and later on x86_64 (commit $commit)

Double-click grainscope.exe for the explorer window (a console window
opens beside it: it shows the program's messages).
In a terminal (PowerShell or cmd), in this folder:
    .\\grainscope.exe run ice-bounce-8ms   a preset without the window
    .\\grainscope.exe --help               every command

The shipped presets are built into the program; presets\\ holds them as
files to copy and edit.
EOF
sed -i 's/$/\r/' "$dir/INSTALL.txt"
pack_zip "$stage" "$name" "$out/$name.zip"

if [ "$macos_and_wheel" = 1 ]; then
    macos_and_wheel
fi
ls -l "$out"
