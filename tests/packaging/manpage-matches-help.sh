#!/usr/bin/env bash
# manpage-matches-help.sh MARBLER MARBLER.1: the manual page says what the help says. The page
# is rendered as man shows it (groff, the man macros) and every help text, `marbler --help` and
# `marbler VERB --help` for each verb it lists, must appear on it word for word, paragraph by
# paragraph in their order; the page must also have its examples.
set -euo pipefail
marbler=$1
page=$2
fail() {
    echo "FAIL: $*" >&2
    exit 1
}
[ -s "$page" ] || fail "no manual page at $page (it is built with the marbler_package_files target)"

# words: the text on stdin as one line of words separated by single spaces, with the typographic
# characters groff may print (hyphens, minus signs, quotes) as the ASCII the help uses.
words() {
    sed -e 's/\xe2\x80\x90/-/g; s/\xe2\x88\x92/-/g; s/\xe2\x80\x99/'"'"'/g; s/\xe2\x80\x98/`/g' \
        -e 's/\xe2\x80\x9c/"/g; s/\xe2\x80\x9d/"/g' | tr -s ' \t\n' '   ' | sed 's/^ *//; s/ *$//'
}

rendered=$(preconv "$page" | groff -man -Tutf8 -rLL=200n -P-cbou 2>&1) ||
    fail "groff cannot render $page: $rendered"
page_words=" $(printf '%s\n' "$rendered" | words) "

# check NAME TEXT: every paragraph of TEXT (lines to a blank line) is on the page word for word,
# the paragraphs in their order.
check() {
    printf '%s\n' "$2" | awk -v page="$page_words" -v name="$1" '
        function norm(s) { gsub(/[ \t]+/, " ", s); sub(/^ /, "", s); sub(/ $/, "", s); return s }
        function flush() {
            p = norm(para); para = ""
            if (p == "") return
            found = index(substr(page, from), " " p " ")
            if (!found) {
                # Say where they part: the longest start of the paragraph found on the page.
                n = split(p, w, " "); prefix = ""
                for (i = 1; i <= n && index(substr(page, from), " " prefix w[i] " "); i++) prefix = prefix w[i] " "
                printf "FAIL: the manual page differs from %s%s at: %s[%s]\n", name,
                    (prefix == "" ? "" : " after \"..." substr(prefix, length(prefix) > 80 ? length(prefix) - 80 : 1) "\""),
                    "", w[i] > "/dev/stderr"
                bad = 1; exit
            }
            from += found + length(p); count++
        }
        BEGIN { from = 1 }
        /^[ \t]*$/ { flush(); next }
        { para = para " " $0 }
        END { if (!bad) flush(); if (bad) exit 1; if (!count) { print "FAIL: " name " printed nothing" > "/dev/stderr"; exit 1 } }
    ' || exit 1
    echo "ok: $1"
}

main_help=$("$marbler" --help)
check "marbler --help" "$main_help"
verbs=$(printf '%s\n' "$main_help" |
    awk '/^verbs:$/ { on = 1; next } on && /^$/ { exit } on && /^  [a-z]/ { print $1 }' | sort -u)
[ "$(echo "$verbs" | wc -l)" -ge 5 ] || fail "too few verbs found in marbler --help: $verbs"
for verb in $verbs; do
    check "marbler $verb --help" "$("$marbler" "$verb" --help)"
done
for section in NAME SYNOPSIS DESCRIPTION COMMANDS EXAMPLES; do
    grep -qx "$section" <<<"$rendered" || fail "the manual page has no $section section"
done
# Every example on the page runs a verb the program has.
while read -r verb; do
    grep -qx "$verb" <<<"$verbs" || fail "an example runs 'marbler $verb', which is no verb"
done < <(printf '%s\n' "$rendered" | sed -n '/^EXAMPLES$/,/^[A-Z]/p' | grep -o 'marbler [a-z]*' | awk '{ print $2 }')
echo "the manual page matches the help of marbler and its $(echo "$verbs" | wc -l) verbs"
