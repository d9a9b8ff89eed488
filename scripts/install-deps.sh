#!/usr/bin/env bash
# Installs the Debian 12 packages ViewPipe needs, only those that are missing.
# Idempotent: a second run installs nothing. Uses sudo when not root.
# --test adds what only the tests need; --pdf only TeX Live, which a lesson's
# handout and slides (`viewpipe lesson export --format pdf`) are set with.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache lld
  libeigen3-dev nlohmann-json3-dev libcli11-dev libfmt-dev libfast-float-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libboost-dev libmpfr-dev libglm-dev
  qtbase5-dev libqt5svg5-dev libvtk9-dev libvtk9-qt-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core fonts-dejavu-extra
  ffmpeg
  libjs-three libjs-katex
  emscripten
)
# Only the tests need these (sanitizers, libFuzzer, TeX to compile the LaTeX and
# TikZ exports, poppler to rasterize PDFs, Chromium to open the web page):
# `make run` stays quick.
tex=(texlive-latex-base texlive-latex-recommended texlive-latex-extra texlive-pictures texlive-fonts-recommended)
case "${1:-}" in
  --test) packages+=(clang libclang-rt-14-dev "${tex[@]}" poppler-utils chromium) ;;
  --pdf) packages+=("${tex[@]}") ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=()
[ "$(id -u)" -ne 0 ] && sudo=(sudo)
echo "Installing missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
