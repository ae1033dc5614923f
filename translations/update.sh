#!/usr/bin/env bash
# Gathers the window's words from app/ into translations/marbler_*.ts (Qt's lupdate), keeping
# what is translated, marking new words unfinished and dropping words no longer in the source.
# Then lists what is left to translate; the build compiles the .ts files (app/CMakeLists.txt).
#
#   translations/update.sh            update, and list the unfinished entries
#   translations/update.sh --check    the same, and exit 1 when any entry is unfinished
#
# Some files translate through a helper of their own (Help.cpp's helpText, ...); lupdate is told
# those names with -tr-function-alias. A new helper needs its name here, or its words are missed.
set -euo pipefail
cd "$(dirname "$0")/.."

# The registry's words (genome/, breed/: no Qt there) as a list lupdate reads.
python3 translations/registry_words.py
LUPDATE=${LUPDATE:-$(command -v lupdate6 || command -v /usr/lib/qt6/bin/lupdate || echo lupdate)}
"$LUPDATE" -silent -locations relative -no-obsolete -extensions cpp,h \
    -tr-function-alias tr+=helpText,tr+=lineageText,tr+=bathTr,tr+=languageText \
    app translations/registry-words.cpp -ts translations/marbler_tr.ts translations/marbler_de.ts

unfinished=0
for ts in translations/marbler_*.ts; do
    count=$(grep -c 'type="unfinished"' "$ts" || true)
    echo "$ts: $count unfinished"
    if [ "$count" -gt 0 ]; then
        unfinished=1
        # Each unfinished source text, so whoever translates sees the gaps at once.
        python3 - "$ts" <<'PY'
import sys, xml.etree.ElementTree as ET
for context in ET.parse(sys.argv[1]).getroot().iter("context"):
    for message in context.iter("message"):
        if message.find("translation").get("type") == "unfinished":
            print("  [%s] %s" % (context.findtext("name"), message.findtext("source").replace("\n", "\\n")))
PY
    fi
done
if [ "${1:-}" = "--check" ] && [ "$unfinished" = 1 ]; then exit 1; fi
exit 0
