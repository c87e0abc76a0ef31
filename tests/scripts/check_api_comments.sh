#!/usr/bin/env bash
# check_api_comments.sh SOURCE -- every public function has its comment.
#
# In include/karma/*.h, each ME_API function declaration must be documented: by a comment ending on
# the line just above it, by a trailing /**< ... */ comment, or by the comment heading the run of
# declarations it belongs to (consecutive lines, no blank line between: a Get/Set family under one
# sentence). A declaration after a blank line or after code with no comment fails the check.
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
            if (stripped ~ /^ME_API / && stripped ~ /\(/) {
                if (!covered && stripped !~ /\/\*\*</) print file ":" NR ": " name_of(stripped)
                covered = 1                     # the run continues under the same comment
                if (stripped !~ /;/) indecl = 1
                next
            }
            covered = (stripped ~ /\*\/$/)       # a comment just ended: it covers what follows
        }' "$h"
done)
if [ -n "$missing" ]; then
    echo "$missing"
    echo "$(echo "$missing" | wc -l) public functions without a comment: give each its one line (what it does,"
    echo "units, ownership, what it rejects), or place it in a commented run of its family"
    exit 1
fi
echo "every ME_API function in include/karma has its comment"
