#!/bin/sh
# Peak memory (resident set) of the app opening the house alone and the house
# beside wavy-sheet meshes of 10^5, 10^6 and 3·10^6 triangles (binary PLY),
# as `viewpipe open SCENE --screenshot` (the window built, every stage's
# props made, one frame drawn). Needs GNU time (Debian package `time`) and a
# display (run under xvfb-run -a -s "-screen 0 1920x1080x24").
#   bench/peak_memory.sh [BUILD_DIR]   (default: build)
set -eu
build=${1:-build}
viewpipe=$build/bin/viewpipe
writer=$build/bench/write_sheet_mesh
[ -x /usr/bin/time ] || { echo "peak_memory.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }
[ -x "$viewpipe" ] && [ -x "$writer" ] || { echo "peak_memory.sh: build $viewpipe and $writer first" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
house=$(dirname "$0")/../data/scenes/house.json

# Prints the peak resident set, in MB, of opening a scene.
peak() {
    /usr/bin/time -f %M -o "$dir/kb" "$viewpipe" open "$1" --screenshot "$dir/shot.png" >/dev/null 2>&1
    echo $(( $(cat "$dir/kb") / 1024 ))
}

base=$(peak "$house")
printf '%-12s %10s %10s %14s %18s\n' triangles "file MB" "peak MB" "above house" "bytes/triangle"
printf '%-12s %10s %10d %14s %18s\n' "house alone" - "$base" - -
for triangles in 100000 1000000 3000000; do
    "$writer" "$dir/sheet.ply" "$triangles"
    sed 's|"objects": \[|"objects": [ { "type": "mesh", "path": "sheet.ply" },|' "$house" >"$dir/scene.json"
    mb=$(( $(stat -c %s "$dir/sheet.ply") / 1048576 ))
    total=$(peak "$dir/scene.json")
    above=$((total - base))
    printf '%-12s %10d %10d %14d %18d\n' "$triangles" "$mb" "$total" "$above" $((above * 1048576 / triangles))
done
