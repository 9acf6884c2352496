#!/usr/bin/env bash
# Starts the real window under Xvfb with Mesa's software OpenGL, takes a
# screenshot and checks that it is not blank.
# Usage: .ci/smoke-window.sh PATH-TO-GRAINSCOPE [SCREENSHOT.png [ARGUMENTS...]]
# ARGUMENTS go to grainscope (e.g. `gui some-preset.ron`); the screen is
# $SCREEN (default 1440x920), the screenshot taken $WAIT seconds after the start
# (default 10); the window's output is kept in $APP_LOG if set.
set -euo pipefail
bin=$1
shot=${2:-$(mktemp -d)/grainscope-window.png}
shift $(( $# < 2 ? $# : 2 ))
screen=${SCREEN:-1440x920}

need=()
command -v Xvfb >/dev/null || need+=(xvfb)
command -v import >/dev/null || need+=(imagemagick)
if [ ${#need[@]} -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" libgl1-mesa-dri libegl1 >/dev/null
fi

home=$(mktemp -d)            # a fresh session, not the user's
display=:$((90 + RANDOM % 50))
Xvfb "$display" -screen 0 "${screen}x24" >/dev/null 2>&1 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 2
HOME=$home DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1 "$bin" "$@" >"$home/app.log" 2>&1 &
app=$!
sleep "${WAIT:-10}"
if ! kill -0 "$app" 2>/dev/null; then
    echo "smoke test: the window exited early:" >&2
    cat "$home/app.log" >&2
    exit 1
fi
DISPLAY=$display import -window root "$shot"
if [ -n "${APP_LOG:-}" ]; then cp "$home/app.log" "$APP_LOG"; fi
sd=$(identify -format '%[fx:standard_deviation]' "$shot")
colors=$(identify -format '%k' "$shot")
echo "smoke test: screenshot $shot, standard deviation $sd, $colors colours"
awk -v sd="$sd" -v c="$colors" 'BEGIN { exit !(sd > 0.02 && c > 50) }' || {
    echo "smoke test: the screenshot is blank" >&2
    exit 1
}
