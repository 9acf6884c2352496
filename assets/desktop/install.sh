#!/bin/sh
# Installs grainscope for this user: the command in $PREFIX/bin, a menu entry
# and its icon under $PREFIX/share (PREFIX defaults to ~/.local).
# ./install.sh --uninstall removes them again.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
prefix=${PREFIX:-$HOME/.local}
bin="$prefix/bin/grainscope"
entry="$prefix/share/applications/grainscope.desktop"
icon="$prefix/share/icons/hicolor/scalable/apps/grainscope.svg"
if [ "${1:-}" = "--uninstall" ]; then
    rm -f "$bin" "$entry" "$icon"
    echo "removed $bin, $entry and $icon"
    exit 0
fi
mkdir -p "$prefix/bin" "$(dirname "$entry")" "$(dirname "$icon")"
cp "$here/grainscope" "$bin.tmp" && chmod 755 "$bin.tmp" && mv "$bin.tmp" "$bin"
# The menu entry names the command by its full path: ~/.local/bin need not be on PATH.
sed "s|^Exec=grainscope |Exec=$bin |" "$here/share/applications/grainscope.desktop" >"$entry"
cp "$here/share/icons/hicolor/scalable/apps/grainscope.svg" "$icon"
command -v update-desktop-database >/dev/null && update-desktop-database -q "$(dirname "$entry")" 2>/dev/null || true
echo "installed $bin, a menu entry ($entry) and its icon"
case ":$PATH:" in
    *":$prefix/bin:"*) ;;
    *) echo "($prefix/bin is not on your PATH: add it there to type \`grainscope\` in a terminal)" ;;
esac
