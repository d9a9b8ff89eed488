#!/usr/bin/env bash
# Shows the built-in default scene's normalizing pipeline.
set -euo pipefail
cd "$(dirname "$0")/.."
exec build/bin/viewpipe pipeline data/scenes/house.json
