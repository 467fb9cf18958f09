#!/usr/bin/env bash
# Installs what RayLab needs on Debian 12 (only what is missing), then configures and
# builds it. Used by scripts/demo.sh and scripts/test.sh; safe to run again.
#
#   scripts/setup.sh [preset] [targets...]     preset: release (default), dev, asan, ci
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${1:-release}"
shift || true

packages=(
  build-essential cmake ninja-build pkg-config git    # compiler and build tools
  xvfb xauth libgl1-mesa-dri libx11-dev               # an X server + software OpenGL for VTK
  libvtk9-dev libvtk9-qt-dev                          # VTK 9.1 with its Qt widget
  qtbase5-dev libqt5opengl5-dev                       # Qt 5 widgets
  qttools5-dev qttools5-dev-tools qttranslations5-l10n  # the window in Chinese (Qt Linguist)
  fonts-noto-cjk fonts-dejavu-core                    # fonts: Chinese text and the UI's Latin
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev     # CGAL exact kernels
  libglm-dev nlohmann-json3-dev libcli11-dev libtbb-dev  # maths, scene files, CLI, threads
  libssl-dev                                          # SHA-256 of the reference cache
  libgtest-dev libgmock-dev libbenchmark-dev          # tests and benchmarks
  clang-format universal-ctags                        # the style checks in the test suite
  clang libclang-rt-14-dev llvm                       # the ASan + fuzz stage (libFuzzer)
  python3-dev python3-numpy pybind11-dev              # the Python module (python/)
  python3-vtk9 python3-pytest python3-matplotlib      # its tests with VTK's Python package
  jupyter-nbconvert python3-ipykernel                 # the example notebook, run headless
  help2man desktop-file-utils appstream               # man page; desktop files' checks
  debootstrap librsvg2-bin                            # package test's fresh root; icon PNGs
  ffmpeg                                              # animate --video and its test (ffprobe)
  chromium                                            # the web export's browser test (headless)
  zip unzip                                           # raylab web --zip (Moodle) and its test
)
# Node.js and npm build the web page's bundle (web/, esbuild + vtk.js); Debian's, unless a
# node is already on PATH (then its own npm comes with it).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "raylab setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  if [[ $(id -u) -eq 0 ]]; then
    apt_get=(apt-get)
  elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
    apt_get=(sudo apt-get)
  else
    echo "raylab setup: not root. Run this once, then run the command again:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${apt_get[@]}" update -qq
  "${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"
fi

cd "$here"
# The web page's npm packages, exactly as web/package-lock.json pins them (no browser is
# downloaded: the test drives Debian's chromium through puppeteer-core). Skipped when
# node_modules was installed after the lock file last changed. --ignore-scripts: no package's
# own install code runs (esbuild finds its binary in @esbuild/linux-x64 without it).
if ! [[ web/node_modules/.package-lock.json -nt web/package-lock.json ]]; then
  echo "raylab setup: npm ci --prefix web"
  PUPPETEER_SKIP_DOWNLOAD=1 npm ci --prefix web --ignore-scripts --no-audit --no-fund
fi
cmake --preset "$preset" >/dev/null
if (($#)); then
  cmake --build --preset "$preset" --target "$@"
else
  cmake --build --preset "$preset"
fi
