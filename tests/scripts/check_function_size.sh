#!/usr/bin/env bash
# check_function_size.sh DIR... -- no function longer than 80 lines or with more than 6 parameters
# without a reason written beside it (issue 16 point 3, docs/conventions.md).
#
# Functions are found by Universal Ctags (Debian's universal-ctags: its line, end and signature
# fields), in the .c and .h files directly in each DIR. A function over either limit passes only when
# the comment just above its definition (the block of comment lines ending on the line before it)
# holds a sentence starting "Size:" that says why it is that long or takes that many parameters.
# Parameters are counted at the signature's top level (a function-pointer parameter counts once).
set -eu
MAX_LINES=80
MAX_PARAMS=6
CTAGS=$(command -v ctags-universal || command -v ctags || true)
if [ -z "$CTAGS" ] || ! "$CTAGS" --version 2>/dev/null | grep -q 'Universal Ctags'; then
    echo "check_function_size.sh: Universal Ctags is needed (apt-get install universal-ctags)" >&2
    exit 2
fi
files=()
for d in "$@"; do
    for f in "$d"/*.c "$d"/*.h; do
        [ -f "$f" ] && files+=("$f")
    done
done
[ ${#files[@]} -gt 0 ] || { echo "check_function_size.sh: no .c or .h file in $*" >&2; exit 2; }
bad=$("$CTAGS" --output-format=u-ctags --fields=+neS --kinds-C=f -o - "${files[@]}" | awk -F'\t' \
        -v maxLines=$MAX_LINES -v maxParams=$MAX_PARAMS '
    # The comment lines ending just above line `at` of file f, joined.
    function comment_above(f, at,    lines, n, i, text, l) {
        n = 0
        while ((getline l < f) > 0 && n < at - 1)
            lines[++n] = l
        close(f)
        text = ""
        for (i = n; i >= 1; i--) {
            if (lines[i] !~ /^[ \t]*(\/\*|\*|\/\/)/ && lines[i] !~ /\*\/[ \t]*$/)
                break
            text = lines[i] " " text
        }
        return text
    }
    {
        line = 0; end = 0; sig = ""
        for (i = 4; i <= NF; i++) {
            if ($i ~ /^line:/) line = substr($i, 6) + 0
            else if ($i ~ /^end:/) end = substr($i, 5) + 0
            else if ($i ~ /^signature:/) sig = substr($i, 11)
        }
        params = 0
        if (sig != "()" && sig != "(void)") {
            params = 1; depth = 0
            for (k = 2; k < length(sig); k++) {
                c = substr(sig, k, 1)
                if (c == "(") depth++
                else if (c == ")") depth--
                else if (c == "," && depth == 0) params++
            }
        }
        length_ = end - line + 1
        if (length_ <= maxLines && params <= maxParams)
            next
        if (comment_above($2, line) ~ /Size:/)
            next
        printf "%s:%d: %s: %d lines, %d parameters\n", $2, line, $1, length_, params
    }')
if [ -n "$bad" ]; then
    echo "$bad"
    echo "$(echo "$bad" | wc -l) functions over $MAX_LINES lines or $MAX_PARAMS parameters without a reason: split them,"
    echo "or say why in a sentence starting \"Size:\" in the comment just above the definition"
    exit 1
fi
echo "no function in $* is over $MAX_LINES lines or $MAX_PARAMS parameters without a reason beside it"
