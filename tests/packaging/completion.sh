#!/usr/bin/env bash
# completion.sh MARBLER COMPLETION-SCRIPT: bash completes marbler's command lines as a user
# meets it: the script is loaded into bash-completion's framework and asked, as a Tab press
# does (COMP_WORDS, COMP_CWORD, COMP_LINE), what follows a partial command line.
set -uo pipefail
marbler=$1
script=$(realpath "$2")
fail() {
    echo "FAIL: $*" >&2
    exit 1
}
framework=/usr/share/bash-completion/bash_completion
[ -r "$framework" ] || fail "bash-completion is not installed ($framework)"
# The framework runs in an interactive-like shell: no -e and no -u, as bash runs it.
set +u
# shellcheck disable=SC1090
source "$framework"
# shellcheck disable=SC1090
source "$script"
[ "$(complete -p marbler 2>/dev/null)" = "complete -F _marbler marbler" ] ||
    fail "$script does not register _marbler for marbler"

# The marbler under test is the one found on PATH, as an installed one would be.
bin=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$bin" "$work"' EXIT
ln -s "$(realpath "$marbler")" "$bin/marbler"
PATH=$bin:$PATH
cd "$work" || exit 1
mkdir designs
touch stones.marble.json picture.png scan.tif notes.txt mesh.stl movie.mp4 rounds.json

# complete LINE: what Tab offers at the end of LINE ("marbler render --a"), sorted, one a line.
complete_line() {
    COMP_LINE=$1
    COMP_POINT=${#COMP_LINE}
    read -ra COMP_WORDS <<<"$COMP_LINE"
    [[ $COMP_LINE == *" " ]] && COMP_WORDS+=("")
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMPREPLY=()
    _marbler marbler "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
    printf '%s\n' "${COMPREPLY[@]}" | sort -u
}
# expect LINE WORD...: Tab after LINE offers every WORD
expect() {
    local line=$1 got w
    shift
    got=$(complete_line "$line")
    for w in "$@"; do
        grep -qxF -- "$w" <<<"$got" || fail "'$line<Tab>' does not offer '$w'; it offers: $(echo $got)"
    done
}
# refuse LINE WORD...: Tab after LINE offers none of the WORDs
refuse() {
    local line=$1 got w
    shift
    got=$(complete_line "$line")
    for w in "$@"; do
        grep -qxF -- "$w" <<<"$got" && fail "'$line<Tab>' offers '$w'; it offers: $(echo $got)"
    done
    return 0
}

# Verbs: every verb `marbler --help` lists, and genome files (the window opens them).
verbs=$(marbler --help | awk '/^verbs:$/ { on = 1; next } on && /^$/ { exit } on && /^  [a-z]/ { print $1 }')
[ "$(echo "$verbs" | sort -u | wc -l)" -ge 5 ] || fail "too few verbs in marbler --help"
# shellcheck disable=SC2086
expect "marbler " $verbs stones.marble.json picture.png designs
expect "marbler re" render
refuse "marbler re" random svg stones.marble.json
expect "marbler --s" --solid --seed --screenshot

# Options: every option of every verb's help, for that verb (info and doctor list none).
with_options=0
for verb in $verbs; do
    options=$(marbler "$verb" --help | grep '^  -[^ ]' | cut -c3- | sed 's/  .*//' | grep -o -- '--\?[a-z][a-z0-9-]*' | sort -u)
    [ -n "$options" ] || continue
    # shellcheck disable=SC2086
    expect "marbler $verb -" $options
    with_options=$((with_options + 1))
done
[ "$with_options" -ge 5 ] || fail "only $with_options verbs have options in their help"
expect "marbler render --wi" --width
refuse "marbler render --wi" --height --dimension
refuse "marbler svg -" --mesh

# Operators and families, as the program names them.
operators=$(marbler breed --help | awk '/^operators:$/ { on = 1; next } on && /^$/ { exit } on && /^  [a-z]/ { print $1 }')
[ -n "$operators" ] || fail "no operators in marbler breed --help"
# shellcheck disable=SC2086
expect "marbler breed " $operators
refuse "marbler breed " stones.marble.json
expect "marbler breed alter " stones.marble.json picture.png
expect "marbler breed alter stones.marble.json --seed 3 " stones.marble.json
families=$(marbler random --families | awk '{ print $1 }')
[ -n "$families" ] || fail "marbler random --families names no family"
# shellcheck disable=SC2086
expect "marbler random --family " $families
first=$(echo "$families" | head -1)
expect "marbler random --family ${first:0:3}" "$first"
expect "marbler random --family=${first:0:3}" "$first"

# Values from the help's own lists.
expect "marbler render stones.marble.json --aa gr" grid2 grid8
expect "marbler render stones.marble.json --mesh " vase teapot mesh.stl designs
refuse "marbler render stones.marble.json --mesh " notes.txt picture.png
expect "marbler bake stones.marble.json --slices " x y z
expect "marbler paper --recipe " post classic

# File types by extension: genomes where a genome goes, the output's types after -o.
expect "marbler render " stones.marble.json picture.png scan.tif designs
refuse "marbler render " notes.txt movie.mp4 rounds.json
refuse "marbler render stones.marble.json " stones.marble.json
expect "marbler info " stones.marble.json
expect "marbler render stones.marble.json -o " picture.png scan.tif designs
refuse "marbler render stones.marble.json -o " stones.marble.json notes.txt
expect "marbler render stones.marble.json --width 512 -o " picture.png
expect "marbler animate stones.marble.json -o " movie.mp4 designs
refuse "marbler animate stones.marble.json -o " picture.png
expect "marbler video stones.marble.json " movie.mp4
expect "marbler breed --picks " rounds.json
refuse "marbler render stones.marble.json --width " picture.png stones.marble.json
expect "marbler --screenshot " picture.png
refuse "marbler --screenshot " stones.marble.json
# Under `set -o pipefail`, as here and perhaps in a user's shell, a pipeline whose reader leaves
# early (`printf ... | grep -q`) fails now and then: the writer dies of SIGPIPE once grep has
# gone. The completion once offered files after --mesh that way, about one run in hundreds.
if awk '!/^[[:space:]]*#/ && /\|[[:space:]]*grep[[:space:]]+(-[[:alnum:]]*q|--quiet)/ {
            print FILENAME ":" FNR ": " $0; found = 1 } END { exit !found }' "$script" >&2; then
    fail "$script pipes into grep -q, which fails now and then under pipefail"
fi
echo "completion offers verbs, options, operators, families and files as the program lists them"
