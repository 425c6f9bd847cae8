# Plots bench_complexity's CSV (book §10.7): time per ray and build time against the number
# of triangles, log-log, one line per structure, for each input.
#   gnuplot -e "csv='complexity.csv'; out='DIR'" bench/complexity.gnuplot
set datafile separator ','
set terminal pngcairo size 960,420 font 'sans,10'
set logscale xy
set grid
set key top left
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'triangles'
structures = 'none bvh-sort bvh-midpoint bvh-sah grid bsp-midpoint bsp fast'
rows(input, s) = sprintf("< awk -F, '$1 == \"%s\" && $3 == \"%s\"' %s", input, s, csv)
do for [input in 'terrain soup stadium'] {
    set output out.'/complexity-'.input.'.png'
    set multiplot layout 1,2 title input
    set ylabel 'ns per ray'
    plot for [i=1:words(structures)] rows(input, word(structures, i)) using 2:5 with linespoints lc i pt i title word(structures, i)
    set ylabel 'build seconds'
    plot for [i=2:words(structures)] rows(input, word(structures, i)) using 2:4 with linespoints lc i pt i title word(structures, i)
    unset multiplot
}
