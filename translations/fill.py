#!/usr/bin/env python3
"""Writes the translations of words*.py into marbler_tr.ts and marbler_de.ts.

Run translations/update.sh first (lupdate gathers the words), then this, then update.sh again
(lupdate's own layout). The tables win for the words they hold; other entries are kept as
translated by hand (Qt Linguist), and those left unfinished are listed.
Each translation is checked: the same placeholders (%1, %L1, %n) and an & where the source has
one. Exits 1 when a check fails or an entry is left unfinished."""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
TABLE = {}
for path in sorted(glob.glob(os.path.join(HERE, "words*.py"))):
    module = {}
    exec(compile(open(path, encoding="utf-8").read(), path, "exec"), module)
    for source, turkish, german in module["WORDS"]:
        TABLE[source] = {"tr": turkish, "de": german}

PLACEHOLDER = re.compile(r"%L?[0-9]+|%n")


def problems(source, text):
    found = []
    if sorted(set(PLACEHOLDER.findall(source))) != sorted(set(PLACEHOLDER.findall(text))):
        found.append("placeholders differ")
    # An accelerator (&x, not the &amp; of HTML) where the source has one.
    accel = lambda s: re.search(r"&(?!amp;|lt;|gt;)\S", s) is not None
    if accel(source) != accel(text):
        found.append("accelerator differs")
    return found


def fill(ts_path, language):
    tree = ET.parse(ts_path)
    missing, bad = [], []
    for context in tree.getroot().iter("context"):
        for message in context.iter("message"):
            source = message.findtext("source")
            translation = message.find("translation")
            entry = TABLE.get(source)
            if entry is None:
                # Not in the tables: kept as translated by hand (in Qt Linguist), or missing.
                if translation.get("type") == "unfinished":
                    missing.append((context.findtext("name"), source))
                continue
            text = entry[language]
            forms = list(text) if isinstance(text, tuple) else [text]
            for form in forms:
                for problem in problems(source, form):
                    bad.append((source, form, problem))
            if message.get("numerus") == "yes":
                slots = translation.findall("numerusform")
                for i, slot in enumerate(slots):
                    slot.text = forms[min(i, len(forms) - 1)]
            else:
                translation.text = forms[0]
            translation.attrib.pop("type", None)
    tree.write(ts_path, encoding="utf-8", xml_declaration=True)
    # ElementTree drops the doctype lupdate writes; put it back so the file diffs cleanly.
    text = open(ts_path, encoding="utf-8").read()
    text = text.replace("<?xml version='1.0' encoding='utf-8'?>\n", '<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n', 1)
    open(ts_path, "w", encoding="utf-8").write(text + ("" if text.endswith("\n") else "\n"))
    return missing, bad


status = 0
for language in ("tr", "de"):
    path = os.path.join(HERE, "marbler_%s.ts" % language)
    missing, bad = fill(path, language)
    for context, source in missing:
        print("%s: no translation: [%s] %r" % (language, context, source))
    for source, text, problem in bad:
        print("%s: %s: %r -> %r" % (language, problem, source, text))
    if missing or bad:
        status = 1
sys.exit(status)
