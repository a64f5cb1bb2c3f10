#!/bin/sh
# csv_equal.sh A.csv B.csv LABEL_A LABEL_B: exit 0 when the two bench.csv
# files have the same header and rows, equal in every column but the
# timings (*_ms, pvs_over_full); else one FAIL line per difference, exit 1.
awk -F, -v la="$3" -v lb="$4" '
    NR == FNR { if (FNR == 1) { head = $0; for (i = 1; i <= NF; i++) if ($i ~ /_ms$/ || $i == "pvs_over_full") skip[i] = 1 }
                else row[FNR] = $0
                na = FNR; next }
    FNR == 1 { if ($0 != head) { print "FAIL: headers differ"; bad = 1 } next }
    { split(row[FNR], a, ","); nb = FNR
      for (i = 1; i <= NF; i++) if (!skip[i] && a[i] != $i) { print "FAIL: row " FNR - 1 " column " i ": " a[i] " (" la ") vs " $i " (" lb ")"; bad = 1 } }
    END { if (na != nb) { print "FAIL: " na - 1 " " la " rows, " nb - 1 " " lb; bad = 1 }
          if (bad) exit 1
          print "ok: " na - 1 " rows equal in every non-timing column (" la ", " lb ")" }' "$1" "$2"
