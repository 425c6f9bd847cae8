# Plots bench_time_error's CSV (book §14.5): RMSE against samples per pixel and against wall
# time, log-log, one line per pattern, for each scene.
#   gnuplot -e "csv='time-error.csv'; out='DIR'; scenes='checker edges'" bench/time_error.gnuplot
set datafile separator ','
set terminal pngcairo size 960,420 font 'sans,10'
set logscale xy
set grid
set key top right
set format y '10^{%L}'
set ylabel 'RMSE (linear)'
patterns = 'random jittered'
rows(scene, p) = sprintf("< awk -F, '$1 == \"%s\" && $2 == \"%s\"' %s", scene, p, csv)
do for [scene in scenes] {
    set output out.'/time-error-'.scene.'.png'
    set multiplot layout 1,2 title scene
    set xlabel 'samples per pixel'
    set format x '%g'
    plot for [i=1:words(patterns)] rows(scene, word(patterns, i)) using 3:6 with linespoints lc i pt i title word(patterns, i)
    set xlabel 'seconds per image'
    set format x '10^{%L}'
    plot for [i=1:words(patterns)] rows(scene, word(patterns, i)) using 4:6 with linespoints lc i pt i title word(patterns, i)
    unset multiplot
}
