#!/usr/bin/env bash
# Makes the icon's PNG sizes from raylab.svg (Debian: librsvg2-bin). Run after editing it.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
for size in 16 32 48 64 128 256; do
  rsvg-convert --width "$size" --height "$size" raylab.svg --output "raylab-$size.png"
done
