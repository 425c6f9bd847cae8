# Plots bench_complexity's CSV (book §10.7): time per ray and build time against the number
# of triangles, log-log, one line per structure, for each input.
#   gnuplot -e "csv='complexity.csv'; out='DIR'" bench/complexity.gnuplot
set datafile separator ','
set terminal pngcairo size 900,420 font 'sans,10'
set logscale xy
set grid
set key outside right
set xlabel 'triangles'
structures = 'none bvh-sort bvh-midpoint bvh-sah fast'
do for [input in 'terrain soup'] {
    set output out.'/complexity-'.input.'.png'
    set multiplot layout 1,2 title input
    set ylabel 'ns per ray'
    plot for [s in structures] csv using (strcol(1) eq input && strcol(3) eq s ? $2 : 1/0):5 \
        with linespoints title s
    set ylabel 'build seconds'
    plot for [s in structures] csv using (strcol(1) eq input && strcol(3) eq s && s ne 'none' ? $2 : 1/0):4 \
        with linespoints title s
    unset multiplot
}
