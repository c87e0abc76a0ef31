#!/usr/bin/env bash
# check_listings.sh SOURCE EXAMPLES_BIN -- every listing in the documents is a tested file, shown exactly.
#
# In README.md and docs/**/*.md, a fenced block right after the line
#   <!-- listing: PATH -->   must be the file PATH of the repository, character for character;
#   <!-- output: PATH -->    must be what the example PATH (examples/X/Y.c, built by tests/cmake/examples.cmake
#                            as example_X_Y in EXAMPLES_BIN) prints.
# In docs/guide/, every ```c block must be a listing: the guide's code is compiled and run by the suite.
set -eu
source=$1 bin=$2
cd "$source"
status=0 listings=0 outputs=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
docs=$(ls README.md; find docs -name '*.md' | sort)
for doc in $docs; do
    # Splits the document into $tmp/N.kind, $tmp/N.path, $tmp/N.block; reports unlisted C blocks in the guide.
    rm -f "$tmp"/*.block "$tmp"/*.kind "$tmp"/*.path
    awk -v dir="$tmp" -v guide="$(case $doc in docs/guide/*) echo 1;; *) echo 0;; esac)" -v doc="$doc" '
        /^<!-- (listing|output): [^ ]+ -->$/ { kind = $2; sub(/:$/, "", kind); path = $3; armed = NR + 1; next }
        /^```/ && !inblock {
            inblock = 1
            if (NR == armed) { n++; file = dir "/" n ".block"; print kind > (dir "/" n ".kind"); print path > (dir "/" n ".path"); printf "" > file }
            else { file = ""; if (guide && $0 == "```c") { print doc ":" NR ": a C block that is not a listing of examples/" > "/dev/stderr"; bad = 1 } }
            next
        }
        /^```/ && inblock { inblock = 0; if (file != "") close(file); file = ""; next }
        inblock && file != "" { print > file }
        END { exit bad }' "$doc" || status=1
    for k in "$tmp"/*.kind; do
        [ -e "$k" ] || continue
        n=${k%.kind}; kind=$(cat "$k"); path=$(cat "$n.path")
        if [ ! -f "$path" ]; then echo "$doc: $kind of $path, which does not exist"; status=1; continue; fi
        if [ "$kind" = listing ]; then
            listings=$((listings + 1))
            diff -u "$path" "$n.block" >/dev/null || { echo "$doc shows $path differently:"; diff -u "$path" "$n.block" || true; status=1; }
        else
            outputs=$((outputs + 1))
            rel=${path#examples/}; exe="$bin/example_$(echo "${rel%.c}" | tr / _)"
            if [ ! -x "$exe" ]; then echo "$doc: $exe (the output of $path) was not built"; status=1; continue; fi
            "$exe" > "$n.actual" || { echo "$exe failed"; status=1; continue; }
            diff -u "$n.block" "$n.actual" >/dev/null || { echo "$doc shows the output of $path differently (- doc, + program):"; diff -u "$n.block" "$n.actual" || true; status=1; }
        fi
    done
done
echo "$listings listings and $outputs outputs checked"
exit $status
