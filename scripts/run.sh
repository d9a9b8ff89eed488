#!/usr/bin/env bash
# Opens the app on the built-in default scene. With no display, says so and
# saves a picture of every stage of the default scene instead.
set -euo pipefail
cd "$(dirname "$0")/.."
viewpipe=build/bin/viewpipe
scene=data/scenes/house-corner.json

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec "$viewpipe" open "$scene"
fi

out=out/house-stages
mkdir -p "$out"
stages=$("$viewpipe" pipeline "$scene" --json | grep -o '"symbol"' | wc -l)
echo "No display found (DISPLAY is not set): saving the default scene's stages to $out/ instead."
# One virtual display for all the screenshots.
xvfb-run -a -s "-screen 0 1920x1080x24" bash -c '
  for k in $(seq 0 "$1"); do
    "$2" open "$3" --stage "$k" --screenshot "$4/stage-$k.png" 2>/dev/null
    echo "  $4/stage-$k.png"
  done' _ "$stages" "$viewpipe" "$scene" "$out"
echo "Open them with any image viewer, or run 'make run' where there is a display."
