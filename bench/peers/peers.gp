# The peers' work-precision plot of one icosphere level: gnuplot -e "level=3" bench/peers/peers.gp, run in the folder
# that holds peers_LEVEL.csv (bench/run_peers.sh); writes peers_LEVEL.png there. One panel per scene: CPU s of one
# thread per simulated s against the worst volume error from softbody's rk45 reference, one curve per program and
# setting family (Jolt: one curve per iteration count over dt 1/60 .. 1/1920 s; softbody: xpbd over its substeps,
# vbd per sweep count over its substeps). Failed runs (error inf) are left out.
if (!exists("level")) level = 3
data = sprintf("peers_%d.csv", level)
set terminal pngcairo size 1500,620 font "DejaVu Sans,11"
set output sprintf("peers_%d.png", level)
set datafile separator ","
set logscale xy
set grid
set xlabel "worst volume error against the reference [%]"
set ylabel "CPU s per simulated s (one thread)"
families = "jolt_it1 jolt_it2 jolt_it5 jolt_it10 jolt_it20 jolt_it40 xpbd_fixed xpbd_auto vbd_it4 vbd_it8"
titles = "'Jolt, 1 iteration' 'Jolt, 2 iterations' 'Jolt, 5 iterations' 'Jolt, 10 iterations' 'Jolt, 20 iterations' 'Jolt, 40 iterations' 'softbody xpbd, substeps 2..64' 'softbody xpbd, auto' 'softbody vbd, 4 sweeps, substeps 1,2,4' 'softbody vbd, 8 sweeps, substeps 1,2,4'"
# Jolt in blues and greys (darker: more iterations), softbody in reds (xpbd) and greens (vbd)
colours = "#9ecae1 #6baed6 #4292c6 #2171b5 #08519c #08306b #e31a1c #000000 #74c476 #238b45"
rows(scene, family) = sprintf("< awk -F, '$1==\"%s\" && $4==\"%s\" && $9!=\"inf\"' %s", scene, family, data)
set multiplot layout 1,2 margins 0.06,0.78,0.11,0.9 spacing 0.07 title sprintf("icosphere level %d: CPU cost against volume error (Jolt over dt 1/60 .. 1/1920 s)", level)
set title "breathing in flight, 1 s (no gravity, no floor, no dampers)"
unset key
plot for [i=1:words(families)] rows("breathing", word(families, i)) using 9:8 with linespoints lw 2 lc rgb word(colours, i) pt (i < 7 ? 7 : 5) ps 1 title word(titles, i)
set title "bounce, first impact 0-1.2 s"
set key at screen 0.995,0.88 right top
plot for [i=1:words(families)] rows("bounce", word(families, i)) using 9:8 with linespoints lw 2 lc rgb word(colours, i) pt (i < 7 ? 7 : 5) ps 1 title word(titles, i)
unset multiplot
