#!/usr/bin/env python3
"""Fills unfinished messages of a Qt Linguist .ts file from a table (source -> translation).

Used by maintainers after scripts/update-translations.sh:
    scripts/fill_ts.py app/i18n/raylab_zh_CN.ts table.tsv
where each line of table.tsv is `source<TAB>translation` (sources as they appear in the
C++ code, with \\n for a line break; an optional third column is the disambiguating
comment). Prints the sources still unfinished.
"""
import html
import re
import sys


def main(ts_path, table_path):
    table = {}
    with open(table_path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            parts = line.split("\t")
            source, translation = parts[0], parts[1]
            comment = parts[2] if len(parts) > 2 else ""
            table[(source.replace("\\n", "\n"), comment)] = translation.replace("\\n", "\n")
    text = open(ts_path, encoding="utf-8").read()
    pattern = re.compile(
        r'(<message>\s*<source>([^<]*)</source>\s*(?:<comment>([^<]*)</comment>\s*)?)'
        r'<translation type="unfinished">[^<]*</translation>')

    def fill(m):
        source = html.unescape(m.group(2))
        key = (source, html.unescape(m.group(3) or ""))
        if key not in table:
            return m.group(0)
        escaped = html.escape(table[key], quote=False).replace("'", "&apos;").replace('"', "&quot;")
        return m.group(1) + "<translation>" + escaped + "</translation>"

    text = pattern.sub(fill, text)
    open(ts_path, "w", encoding="utf-8").write(text)
    for m in pattern.finditer(text):
        print("unfinished:", html.unescape(m.group(2)))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
