#!/usr/bin/env bash
# Writes DejaVuSans-web.ttf, the browser's font: DejaVu Sans cut to the
# Unicode blocks the explorer's text and a user's Latin, Greek or Cyrillic
# text use (half the size; the browser's module carries it, the desktop
# carries the whole font). Needs fonttools (`pip install fonttools`).
# `cargo test --test presets` checks that it holds every character the
# sources, presets and decks use.
set -euo pipefail
cd "$(dirname "$0")"
blocks=(
    U+0000-024F # Latin, Latin-1, Latin Extended-A and -B
    U+0300-036F # combining marks (ṁ as m and a dot)
    U+0370-03FF # Greek
    U+0400-04FF # Cyrillic
    U+1D00-1DBF # phonetic extensions (superscript letters such as ᵏ)
    U+1E00-1EFF # Latin Extended Additional
    U+2000-206F # general punctuation
    U+2070-209F # superscripts and subscripts
    U+20A0-20CF # currency
    U+2100-214F # letterlike symbols
    U+2150-218F # number forms
    U+2190-21FF # arrows
    U+2200-22FF # mathematical operators
    U+2300-23FF # miscellaneous technical
    U+25A0-25FF # geometric shapes
    U+2600-26FF # miscellaneous symbols (☉)
    U+2700-27BF # dingbats
    U+27C0-27EF # miscellaneous mathematical symbols A (⟨ ⟩)
    U+FFFD      # the replacement character
)
unicodes=$(printf '%s,' "${blocks[@]}")
pyftsubset DejaVuSans.ttf --unicodes="${unicodes%,}" --layout-features='*' --glyph-names \
    --notdef-outline --output-file=DejaVuSans-web.ttf
