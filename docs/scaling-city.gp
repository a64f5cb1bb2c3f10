# docs/scaling-city.png: PVS time against scene size on builtin:city?tris=T (docs/results.md,
# "Output-sensitive scaling"); data from that table. gnuplot docs/scaling-city.gp
set terminal pngcairo size 720,420 font ",10"
set output "docs/scaling-city.png"
$d << EOD
# scene_tris pvs_tris pvs_ms full_ms
150406 14416 4393 120.6
600336 35066 6627 346.5
2400872 239496 17577 828.9
EOD
set logscale xy
set xrange [100000:3000000]
set xlabel "scene triangles"
set ylabel "ms"
set y2label "PVS ms per 1000 PVS triangles"
set y2tics
set logscale y2
set ytics nomirror
set key top left
set grid
plot $d using 1:3 with linespoints title "PVS (tr, 512x512, delta 10 cm)", \
     $d using 1:4 with linespoints dashtype 2 title "full render, same resolution and FOV", \
     $d using 1:(1000 * $3 / $2) axes x1y2 with linespoints title "PVS ms per 1000 PVS triangles (right)"
