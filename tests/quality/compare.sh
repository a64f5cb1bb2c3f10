#!/bin/sh
# Image-quality regression check (docs/quality.md), POSIX sh + awk.
#
#   compare.sh check  EXPECTED.json SUMMARY.json   fail (exit 1) on any regression, with a table
#   compare.sh update EXPECTED.json SUMMARY.json NOTE  rewrite EXPECTED.json from SUMMARY.json
#                                                   (the metrics below and any the file already has)
#
# EXPECTED.json holds one metric per line:
#   "psnr_mean_db": {"expected": 47.63, "better": "higher", "abs": 0.5, "rel": 0},
# better = higher: regression when got < expected - abs - rel * |expected|
# better = lower:  regression when got > expected + abs + rel * |expected|
# better = equal:  regression when got != expected (run settings, such as the frame count)
# better = near:   regression when |got - expected| > abs + rel * |expected| (both ways: a
#                  PVS that shrinks is as suspect as one that grows)
# "inf" is an infinite PSNR (every frame identical): the best possible for
# "higher", compared as +inf. null (not a number: a broken metric) and a
# missing value always fail. update keeps each metric's
# tolerances and takes new ones from the table below for metrics not yet in
# the file.
set -u

# metric better abs rel: the tolerance table (docs/quality.md explains each)
DEFAULTS='frames equal 0 0
psnr_mean_db higher 0.5 0
psnr_p5_db higher 1.0 0
psnr_min_db higher 2.0 0
fn_pixels_mean lower 0 0
fn_pixels_max lower 0 0
viewcell_miss_frames lower 0 0
pvs_fraction_mean near 0 0.01'

# prints the value of "key" in a flat JSON file ("inf" for an infinite PSNR); exit 1 if absent
value() {
    awk -v key="$2" '!found && match($0, "\"" key "\": *[^,}]+") {
            v = substr($0, RSTART, RLENGTH); sub(/^[^:]*: */, "", v); print v; found = 1 }
        END { exit found ? 0 : 1 }' "$1"
}

mode=${1:-}
expected=${2:-}
summary=${3:-}
[ -f "$summary" ] || { echo "FAIL: summary $summary missing (did the replay run?)"; exit 1; }

case $mode in
update)
    note=${4:-}
    tmp=$expected.tmp
    # the defaults, then the metrics the existing file adds (e.g. a movers replay's dynamic_*)
    table=$DEFAULTS
    if [ -f "$expected" ]; then
        extra=$(grep '"expected":' "$expected" | sed 's/^ *"\([a-z0-9_]*\)".*/\1/' | while read -r key; do
            printf '%s\n' "$DEFAULTS" | grep -q "^$key " || echo "$key x 0 0"
        done)
        [ -n "$extra" ] && table=$(printf '%s\n%s' "$DEFAULTS" "$extra")
    fi
    {
        printf '{\n  "note": "%s",\n  "metrics": {\n' "$note"
        n=0
        total=$(printf '%s\n' "$table" | wc -l)
        printf '%s\n' "$table" | while read -r key better abs rel; do
            n=$((n + 1))
            # keep tolerances already reviewed in the existing file
            if [ -f "$expected" ] && line=$(grep "\"$key\": {" "$expected"); then
                better=$(printf '%s' "$line" | sed 's/.*"better": *"\([a-z]*\)".*/\1/')
                abs=$(printf '%s' "$line" | sed 's/.*"abs": *\([-0-9.e+]*\).*/\1/')
                rel=$(printf '%s' "$line" | sed 's/.*"rel": *\([-0-9.e+]*\).*/\1/')
            fi
            got=$(value "$summary" "$key") || { echo "FAIL: $key not in $summary" >&2; exit 1; }
            sep=,
            [ "$n" -eq "$total" ] && sep=
            printf '    "%s": {"expected": %s, "better": "%s", "abs": %s, "rel": %s}%s\n' \
                "$key" "$got" "$better" "$abs" "$rel" "$sep"
        done || exit 1
        printf '  }\n}\n'
    } >"$tmp" || { rm -f "$tmp"; exit 1; }
    mv "$tmp" "$expected"
    echo "updated $expected from $summary"
    ;;
check)
    [ -f "$expected" ] || { echo "FAIL: $expected missing: generate it (docs/quality.md)"; exit 1; }
    grep '"expected":' "$expected" | while IFS= read -r line; do
        key=$(printf '%s' "$line" | sed 's/^ *"\([a-z0-9_]*\)".*/\1/')
        got=$(value "$summary" "$key") || got=missing
        printf '%s %s\n' "$key" "$got"
        printf '%s\n' "$line"
    done | awk '
        NR % 2 == 1 { key = $1; got = $2; next }
        {
            line = $0
            exp_v = line; sub(/.*"expected": */, "", exp_v); sub(/[,}].*/, "", exp_v)
            better = line; sub(/.*"better": *"/, "", better); sub(/".*/, "", better)
            a = line; sub(/.*"abs": */, "", a); sub(/[,}].*/, "", a)
            r = line; sub(/.*"rel": */, "", r); sub(/[,}].*/, "", r)
            big = 1e300
            e = exp_v == "\"inf\"" ? big : exp_v + 0
            g = got == "\"inf\"" ? big : got + 0
            slack = a + r * (e < 0 ? -e : e)
            number = "^-?[0-9.]+([eE][-+]?[0-9]+)?$"
            if (got == "missing") { ok = 0; lim = "present" }
            else if ((got !~ number && got != "\"inf\"") || (exp_v !~ number && exp_v != "\"inf\"")) { ok = 0; lim = "a number" }
            else if (better == "higher") { lim = e >= big ? ">= inf" : sprintf(">= %.4g", e - slack); ok = g >= e - slack }
            else if (better == "lower") { lim = sprintf("<= %.4g", e + slack); ok = g <= e + slack }
            else if (better == "near") { lim = sprintf("%.4g..%.4g", e - slack, e + slack); ok = g >= e - slack && g <= e + slack }
            else { lim = sprintf("== %s", exp_v); ok = g == e }
            note = ""
            if (ok && better == "higher" && e < big && g > e + slack) note = " (better: consider updating)"
            if (ok && better == "lower" && g < e - slack) note = " (better: consider updating)"
            printf "%-22s expected %-10s got %-10s allowed %-14s %s%s\n", key, exp_v, got, lim, ok ? "ok" : "REGRESSION", note
            if (!ok) bad++
        }
        END {
            if (NR == 0) { print "FAIL: no metrics in the expected file"; exit 1 }
            if (bad) { printf "FAIL: %d metric(s) regressed (tolerances in the expected file; docs/quality.md)\n", bad; exit 1 }
            print "ok: no regression"
        }'
    ;;
*)
    echo "usage: compare.sh check|update EXPECTED.json SUMMARY.json [NOTE]"
    exit 2
    ;;
esac
