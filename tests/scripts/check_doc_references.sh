#!/usr/bin/env bash
# check_doc_references.sh SOURCE -- the documents refer only to what the repository holds.
#
# In README.md, docs/, the public headers, examples/, demos/ and tools/: every path of the repository
# named (docs/..., examples/..., tests/..., include/..., a *.md file) exists, no path climbs out of
# the repository (../), and nothing cites a chapter of a guide the repository does not have.
set -eu
cd "$1"
status=0
files=$(ls README.md; find docs include/karma examples demos tools -type f \( -name '*.md' -o -name '*.h' -o -name '*.c' -o -name '*.sh' -o -name '*.txt' \) | sort)
for f in $files; do
    # Paths written in a document: repository folders followed by a name, and bare Markdown files.
    # A path starts a word (after a space, quote, backtick or bracket); globs (src/me/math_*.c) and
    # docs/karma12.md's paths of Karma 1.2's own SDK are not checked for existence.
    for ref in $(grep -oE '(^|[][ `"(<])(\.\./[A-Za-z0-9_./-]+|(docs|examples|tests|tools|demos|include|src|bench|cmake)/[A-Za-z0-9_./*-]*[A-Za-z0-9_*]|[A-Za-z0-9_-]+\.md)' "$f" \
               | sed 's/^[][ `"(<]//' | sort -u); do
        case $ref in
            ../Resources/*) continue ;; # MeSimpleFile's search path, a run-time location
            ../*) echo "$f: refers to $ref, outside the repository"; status=1; continue ;;
            *'*'*) continue ;;
        esac
        [ "$f" = docs/karma12.md ] && continue
        [ -e "$ref" ] || [ -e "$(dirname "$f")/$ref" ] || [ -e "docs/$ref" ] || { echo "$f: refers to $ref, which does not exist"; status=1; }
    done
    if grep -nE "the guide's chapter|chapter [0-9]+ of the guide" "$f"; then
        echo "$f: cites a chapter of a guide (name the file in docs/guide/ instead)"; status=1
    fi
done
[ $status = 0 ] && echo "every document's references resolve in the repository"
exit $status
