#!/usr/bin/env bash
# What every program shares: --version prints "PROGRAM VERSION" with one
# version string for all of them (the project version, then the git revision
# when built from git); --help shows examples and the exit codes in GNU style
# ("Usage: jtracer-cli [OPTIONS] SCENE", "--width N"); a bad option exits 2
# with a pointer to --help; nothing is coloured.
# Usage: front_ends_test.sh PROJECT_VERSION PROGRAM...
set -euo pipefail
source "$(dirname "$0")/help_options.sh"
project_version=$1
shift

version=
for program in "$@"; do
    name=$(basename "$program")
    line=$("$program" --version)
    [[ $line == "$name "* ]] || fail "$name --version: '$line'"
    this=${line#"$name "}
    [[ $this == "$project_version" || $this == "$project_version (git "*")" ]] ||
        fail "$name --version: '$this' is not $project_version [(git REVISION)]"
    [ -z "$version" ] || [ "$this" = "$version" ] || fail "$name says $this, others $version"
    version=$this

    help=$("$program" --help)
    grep -q 'Example' <<<"$help" || fail "$name --help has no examples"
    grep -q 'Exit codes' <<<"$help" || fail "$name --help does not give the exit codes"
    ! grep -q $'\033' <<<"$help" || fail "$name --help uses colour"
    # GNU style: the program's name (not the path it was run from), operands in
    # capitals, each option's value as a word, never CLI11's types or mappings.
    usage=$(grep -m1 '^Usage:' <<<"$help")
    [[ $usage == "Usage: $name [OPTIONS]"* ]] || fail "$name --help: '$usage'"
    ! grep -qE '[a-z]' <<<"${usage#"Usage: $name [OPTIONS]"}" || fail "$name --help: '$usage'"
    if bad=$(awk '/^  -/ { print $1, $2 }' <<<"$help" | grep -E ' .*(INT|FLOAT|TEXT|->|\{)'); then
        fail "$name --help shows CLI11's value types: $bad"
    fi

    set +e
    err=$("$program" --no-such-option 2>&1 >/dev/null)
    code=$?
    set -e
    [ "$code" = 2 ] || fail "$name --no-such-option exits $code, not 2"
    grep -qF -- "$name --help" <<<"$err" || fail "$name --no-such-option: '$err'"
done
# jtracer-cli's own lines, as its man page gives them.
cli=$1
help=$("$cli" --help)
[ "$(grep -m1 '^Usage:' <<<"$help")" = "Usage: jtracer-cli [OPTIONS] SCENE" ] ||
    fail "jtracer-cli --help: $(grep -m1 '^Usage:' <<<"$help")"
grep -qE '^  --progress MODE +How progress shows on stderr: auto\|bar\|log\|none' <<<"$help" ||
    fail "jtracer-cli --help: $(grep -e '--progress' <<<"$help")"
grep -qE '^  --width N ' <<<"$help" || fail "jtracer-cli --help: $(grep -e '--width' <<<"$help")"
usage=$("$cli" diff --help | grep -m1 '^Usage:')
[ "$usage" = "Usage: jtracer-cli diff [OPTIONS] EXPECTED ACTUAL" ] || fail "jtracer-cli diff --help: $usage"
echo "front ends: $# programs say version $version, give examples and exit codes"
