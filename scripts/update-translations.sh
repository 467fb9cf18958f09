#!/usr/bin/env bash
# Refreshes app/i18n/raylab_zh_CN.ts from the window's sources: new tr() texts are added
# as unfinished (translate them in Qt Linguist, `linguist app/i18n/raylab_zh_CN.ts`, or in
# the XML), texts no longer used are dropped. The test app.TranslationsComplete fails while
# any text of the window has no Chinese translation.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lupdate="$(command -v lupdate || echo /usr/lib/qt5/bin/lupdate)"
cd "$here"
"$lupdate" -silent -no-obsolete -locations none -target-language zh_CN app/src \
  -ts app/i18n/raylab_zh_CN.ts
