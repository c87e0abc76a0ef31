#!/usr/bin/env bash
# check_api_comments.sh SOURCE -- every public function has its own documentation comment.
#
# In include/karma/*.h, each ME_API function declaration, and each static inline function (public too:
# an application calls it as it calls the others), must carry its own Doxygen comment: a /** ... */
# (or /// line) ending on the line just above it, or a trailing /**< ... */ on the declaration. A
# comment heading a run of declarations documents only the first of them, and a plain /* ... */
# comment (a section divider, a note for readers of the header) documents none: each function says
# what it does, with units, ownership and what it rejects (STYLE.md, issue 20).
set -eu
cd "$1"
missing=$(for h in include/karma/*.h; do
    awk -v file="$h" '
        function name_of(s,    t) { t = s; sub(/\(.*/, "", t); n = split(t, w, /[ \t\*]+/); return w[n] }
        {
            line = $0; stripped = line; gsub(/^[ \t]+|[ \t]+$/, "", stripped)
            if (indecl) {                       # continuation of a multi-line declaration
                if (stripped ~ /;/) indecl = 0
                next
            }
            if ((stripped ~ /^ME_API / || stripped ~ /^static inline /) && stripped ~ /\(/) {
                if (!covered && stripped !~ /\/\*\*</) print file ":" NR ": " name_of(stripped)
                covered = 0                     # a comment covers one declaration only
                if (stripped !~ /;/) indecl = 1
                next
            }
            if (stripped ~ /\/\*\*/) doc = 1     # the comment being read is a Doxygen one
            else if (stripped ~ /\/\*/) doc = 0
            covered = (doc && stripped ~ /\*\/$/) || stripped ~ /^\/\/\/ /
        }' "$h"
done)
if [ -n "$missing" ]; then
    echo "$missing"
    echo "$(echo "$missing" | wc -l) public functions without a comment of their own: give each its /** one line */"
    echo "(what it does, units, ownership, what it rejects) just above the declaration"
    exit 1
fi
echo "every ME_API and static inline function in include/karma has its own comment"
