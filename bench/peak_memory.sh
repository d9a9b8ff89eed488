#!/bin/sh
# Peak memory (resident set) of the app opening the house alone and the house
# beside wavy-sheet meshes of 10^5, 10^6 and 3·10^6 triangles (binary PLY),
# as `viewpipe open SCENE --screenshot` (the window built, every stage's
# props made, one frame drawn). Beside it, like for like, a bare VTK viewer
# (bare_vtk_open: VTK's reader, the mesh drawn in two windows the size of the
# app's two views) above its own house. Then, for 10^6 triangles, the window
# against `open --present` and `--layout storyboard` (issue 47: the same
# scene in larger or more views). Needs GNU time (Debian package `time`)
# and a display (run under xvfb-run -a -s "-screen 0 1920x1080x24").
#   bench/peak_memory.sh [BUILD_DIR]   (default: build)
set -eu
build=${1:-build}
viewpipe=$build/bin/viewpipe
writer=$build/bench/write_sheet_mesh
bare=$build/bench/bare_vtk_open
[ -x /usr/bin/time ] || { echo "peak_memory.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }
[ -x "$viewpipe" ] && [ -x "$writer" ] && [ -x "$bare" ] || { echo "peak_memory.sh: build $viewpipe, $writer and $bare first" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
house=$(dirname "$0")/../data/scenes/house.json

# Prints the peak resident set, in MB, of a command.
peak() {
    /usr/bin/time -f %M -o "$dir/kb" "$@" >/dev/null 2>&1
    echo $(( $(cat "$dir/kb") / 1024 ))
}

base=$(peak "$viewpipe" open "$house" --screenshot "$dir/shot.png")
bareBase=$(peak "$bare")
printf '%-12s %10s %10s %14s %18s %22s\n' triangles "file MB" "peak MB" "above house" "bytes/triangle" "bare VTK above house"
printf '%-12s %10s %10d %14s %18s %22s\n' "house alone" - "$base" - - "($bareBase MB)"
for triangles in 100000 1000000 3000000; do
    "$writer" "$dir/sheet.ply" "$triangles"
    sed 's|"objects": \[|"objects": [ { "type": "mesh", "path": "sheet.ply" },|' "$house" >"$dir/scene.json"
    mb=$(( $(stat -c %s "$dir/sheet.ply") / 1048576 ))
    total=$(peak "$viewpipe" open "$dir/scene.json" --screenshot "$dir/shot.png")
    above=$((total - base))
    bareAbove=$(($(peak "$bare" "$dir/sheet.ply") - bareBase))
    printf '%-12s %10d %10d %14d %18d %22d\n' "$triangles" "$mb" "$total" "$above" $((above * 1048576 / triangles)) "$bareAbove"
    if [ "$triangles" = 1000000 ]; then
        window=$total
        present=$(peak "$viewpipe" open "$dir/scene.json" --screenshot "$dir/shot.png" --present)
        storyboard=$(peak "$viewpipe" open "$dir/scene.json" --screenshot "$dir/shot.png" --layout storyboard)
    fi
done
echo
awk -v w="$window" -v p="$present" -v s="$storyboard" 'BEGIN {
    printf "10^6 triangles: window %d MB, --present %d MB (%.2fx), --layout storyboard %d MB (%.2fx)\n", w, p, p / w, s, s / w }'
