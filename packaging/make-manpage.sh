#!/usr/bin/env bash
# make-manpage.sh MARBLER VERSION OUT.1: writes the manual page marbler(1) from the executable's
# own help, `marbler --help` and `marbler VERB --help` for every verb that lists, so the page
# and the help cannot drift apart (tests/packaging/manpage-matches-help.sh checks that every
# word of every help text is on the page, in order). Only the name, the window's options, the
# examples and the files are written here.
#
# The help texts follow one layout, which becomes roff as follows:
#   usage: ... (the first lines, to a blank line)   kept as they are (.nf)
#   a line "options:" (a word or two and a colon)    a heading; the indented lines after it,
#                                                    "  TAG   TEXT" and deeper continuation
#                                                    lines, are a list of tagged paragraphs
#   other lines                                      filled paragraphs; indented lines in them
#                                                    (examples) are kept as they are
set -euo pipefail
if [ $# -ne 3 ]; then
    echo "usage: $0 MARBLER VERSION OUT.1" >&2
    exit 2
fi
marbler=$1
version=$2
out=$3

# to_roff [usage]: help text on stdin -> roff on stdout; "usage": the text begins with usage lines
to_roff() {
    awk -v first="${1:-}" '
    function esc(s) {
        gsub(/\\/, "\\e", s)
        gsub(/-/, "\\-", s)
        gsub(/\x27/, "\\(aq", s)
        gsub(/`/, "\\(ga", s)
        if (s ~ /^\./) s = "\\&" s
        return s
    }
    function verbatim(s) { print ".nf"; print esc(s); print ".fi" }
    BEGIN { mode = first }
    /^[ \t]*$/ { if (mode == "usage") print ".fi"; mode = ""; next }
    mode == "usage" {
        if (!started) { print ".nf"; started = 1 }
        print esc($0); next
    }
    /^[a-z][a-z ]*:$/ { print ".PP"; print "\\fB" esc($0) "\\fR"; mode = "list"; next }
    mode == "list" && /^  [^ ]/ {
        line = substr($0, 3)
        if (match(line, /[^ ]  +[^ ]/)) {
            tag = substr(line, 1, RSTART)
            text = substr(line, RSTART + RLENGTH - 1)
        } else {
            tag = line; text = ""
        }
        print ".TP"; print "\\fB" esc(tag) "\\fR"
        if (text != "") print esc(text)
        next
    }
    mode == "list" { sub(/^ +/, ""); print esc($0); next }
    /^ / { if (mode == "") print ".PP"; mode = "para"; verbatim($0); next }
    { if (mode == "") print ".PP"; mode = "para"; print esc($0) }
    END { if (mode == "usage") print ".fi" }
    '
}

main_help=$("$marbler" --help)
# The verbs are the first words of the "verbs:" list of `marbler --help`, each once.
verbs=$(printf '%s\n' "$main_help" |
    awk '/^verbs:$/ { on = 1; next } on && /^$/ { exit } on && /^  [a-z]/ { print $1 }' | awk '!seen[$0]++')
if [ -z "$verbs" ]; then
    echo "$0: no verbs found in '$marbler --help'" >&2
    exit 1
fi

tmp=$(mktemp "$out.XXXXXX")
trap 'rm -f "$tmp"' EXIT
{
    echo ".\\\" The manual page of marbler, written by packaging/make-manpage.sh from marbler --help."
    echo ".TH MARBLER 1 \"\" \"Marbler $version\" \"User Commands\""
    echo ".nh"
    echo ".ad l"
    echo ".SH NAME"
    echo "marbler \\- breed, edit and render mathematical marbling designs"
    echo ".SH SYNOPSIS"
    printf '%s\n' "$main_help" | awk '/^$/ { exit } { print }' | to_roff usage
    echo ".SH DESCRIPTION"
    echo "Marbler makes marbled designs, flat like paper or solid like carved stone, from"
    echo "closed\\-form, area\\-preserving operations: ink drops, tine lines, combs, waves,"
    echo "circular strokes and vortices.  A design is a short list of these operations, its"
    echo "\\fIgenome\\fR, kept in a genome file (\\fI.marble.json\\fR)."
    echo "Without a verb, \\fBmarbler\\fR opens the workbench window, which breeds designs nine"
    echo "at a time, with the genome files given opened in its grid.  With a verb it works"
    echo "headless."
    printf '%s\n' "$main_help" | awk 'body { print } /^$/ { body = 1 }' | to_roff ""
    echo ".SH OPTIONS"
    echo ".TP"
    echo "\\fB\\-h\\fR, \\fB\\-\\-help\\fR"
    echo "the help above; \\fBmarbler\\fR \\fIVERB\\fR \\fB\\-\\-help\\fR describes a verb"
    echo ".TP"
    echo "\\fB\\-\\-version\\fR"
    echo "the version of Marbler"
    echo ".PP"
    echo "Without a verb these options, and Qt's own (\\fB\\-platform\\fR \\fINAME\\fR,"
    echo "\\fB\\-style\\fR \\fINAME\\fR, ...), go to the window:"
    echo ".TP"
    echo "\\fB\\-\\-solid\\fR, \\fB\\-\\-flat\\fR"
    echo "breed solid (3D) or flat (2D) designs, without the start question"
    echo ".TP"
    echo "\\fB\\-\\-seed\\fR \\fIN\\fR"
    echo "the session's seed, so the first designs are the same each time"
    echo ".TP"
    echo "\\fB\\-\\-screenshot\\fR \\fIFILE\\fR"
    echo "save a picture of the window as FILE and quit"
    echo ".SH COMMANDS"
    for verb in $verbs; do
        echo ".SS \"marbler $verb\""
        "$marbler" "$verb" --help | to_roff usage
    done
    cat <<'EOF'
.SH EXAMPLES
The examples are installed in \fI/usr/share/doc/marbler/examples\fR.
.PP
Render an example at 2048 pixels wide, with antialiasing:
.PP
.nf
.RS
marbler render /usr/share/doc/marbler/examples/five\-stones.marble.json \e
    \-o stones.png \-\-width 2048 \-\-aa rgss
.RE
.fi
.PP
Check a genome and see what it holds:
.PP
.nf
.RS
marbler info stones.png
.RE
.fi
.PP
A random design of the peacock family, then eight children of it:
.PP
.nf
.RS
marbler random \-\-family peacock \-\-seed 7 \-o peacock.marble.json
marbler breed alter peacock.marble.json \-\-seed 1 \-o children
.RE
.fi
.PP
A layered SVG for print at 30 by 30 cm, and a marbled sheet of A4 paper:
.PP
.nf
.RS
marbler svg peacock.marble.json \-o peacock.svg \-\-size 30x30cm
marbler paper \-\-seed 3 \-o paper.png
.RE
.fi
.PP
A solid design on a vase, and its making as a video:
.PP
.nf
.RS
marbler render /usr/share/doc/marbler/examples/slate\-block.marble.json \e
    \-\-mesh vase \-\-view 30,20 \-o vase.png
marbler animate peacock.marble.json \-o making.mp4
.RE
.fi
.SH FILES
.TP
\fI~/.config/Marbler/\fR
the window's remembered settings
.TP
\fI/usr/lib/marbler/\fR
the modules Marbler loads when first needed: image formats, video, the window
.SH SEE ALSO
The genome format and the breeding operators are described in Marbler's documentation,
docs/genome\-format.md and docs/breeding.md in its sources.
EOF
} >"$tmp"
chmod 644 "$tmp"
mv "$tmp" "$out"
trap - EXIT
