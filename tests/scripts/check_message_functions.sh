#!/usr/bin/env bash
# check_message_functions.sh SOURCE -- every message names a function the application can call.
#
# ME_REPORT and the ME_CHECK_* macros (without _IN) report in __func__, the function they sit in: that
# function must be declared in a public header (include/karma/*.h). A check inside an internal helper
# (e.g. a static checkMassRange) must use the _IN form with the public function's name instead.
set -eu
cd "$1"
public=$(grep -ohE '\b[A-Za-z_][A-Za-z0-9_]*[[:space:]]*\(' include/karma/*.h | tr -d ' \t(' | sort -u)
bad=$(for f in $(find src -name '*.c' | sort); do
    awk -v file="$f" '
        # a function definition starts at column 0 and does not end with ";"
        /^[A-Za-z_][A-Za-z0-9_ \t\*]*[ \t\*]([A-Za-z_][A-Za-z0-9_]*)[ \t]*\(/ && !/;[ \t]*$/ && !/^(typedef|return|static inline)/ {
            s = $0; sub(/[ \t]*\(.*/, "", s); n = split(s, w, /[ \t\*]+/); fn = w[n]
        }
        /(ME_REPORT|ME_CHECK_[A-Z0-9_]+)\(/ {
            line = $0
            while (match(line, /(ME_REPORT|ME_CHECK_[A-Z0-9_]+)\(/)) {
                m = substr(line, RSTART, RLENGTH - 1)
                if (m !~ /_IN$/) print file ":" NR ": " m " in " fn
                line = substr(line, RSTART + RLENGTH)
            }
        }' "$f"
done | while read -r where macro in fn; do
    echo "$public" | grep -qx "$fn" || echo "$where $macro in $fn, which the application cannot call"
done)
if [ -n "$bad" ]; then
    echo "$bad"
    echo "messages that name internal functions: use the _IN form with the public function's name"
    exit 1
fi
echo "every ME_REPORT / ME_CHECK_* sits in a public function"
