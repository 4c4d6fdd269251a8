#!/bin/sh
# The comparison drum's zone counts at t = 0 (its first row of NAME.zones) against the same counts
# made here with awk from the published start file (radius x y z per line; zone 1: x > 0 and z > 0,
# zone 2: x < 0 and z < 0; d = 2 mm below a radius of 1.5 mm), after a short run of the driver.
#   checkComparisonZones.sh DRIVER START-FILE [driver flags...]
set -e
driver=$1 start=$2
shift 2
"$driver" --start-file "$start" "$@"
expected=$(awk 'NR > 1 && NF == 4 { s = ($1 < 0.0015) ? 1 : 2;
                  if ($2 > 0 && $4 > 0) a[s]++; if ($2 < 0 && $4 < 0) b[s]++ }
                END { printf "%d %d %d %d", a[1], a[2], b[1], b[2] }' "$start")
got=$(awk '!/^#/ { printf "%d %d %d %d", $2, $3, $4, $5; exit }' ComparisonDrum.zones)
rows=$(grep -vc '^#' ComparisonDrum.zones)
echo "zone counts at t = 0: driver $got, start file $expected; $rows rows"
[ "$got" = "$expected" ] && [ "$rows" -ge 2 ] && echo "zone counts agree with the start file"
