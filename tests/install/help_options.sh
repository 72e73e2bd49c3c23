# Sourced by the tests here: the options a program's --help lists (CLI11's
# layout: an option line starts with two spaces and a dash), one a line,
# short and long names apart: "-o", "--output", ...
help_options() {
    "$@" --help | awk '/^  -/ { print $1 }' | tr ',' '\n' | sed 's/=.*//' | sort -u
}

fail() {
    echo "FAIL: $*" >&2
    exit 1
}
