# The peers' work-precision plot of one icosphere level: gnuplot -e "level=3" bench/peers/peers.gp, run in the folder
# that holds peers_LEVEL.csv (bench/run_peers.sh); writes peers_LEVEL.png there. One panel per scene: CPU s of one
# thread per simulated s against the worst volume error from softbody's rk45 reference, one curve per program and
# setting family (Jolt: one curve per iteration count over dt 1/60 .. 1/1920 s; softbody: xpbd over its substeps,
# vbd per sweep count over its substeps and without its coarse level, symplectic, verlet and rk4 at their "auto" steps, rk45 over its tolerance;
# Bullet per position-iteration count over dt, on the bounce only). Failed runs (error inf) are left out. Also writes peers_breathing_volume_LEVEL.png: the breathing's volume history, where
# Bullet (its own links, not our springs) is shown.
if (!exists("level")) level = 3
data = sprintf("peers_%d.csv", level)
set terminal pngcairo size 1500,620 font "DejaVu Sans,11"
set output sprintf("peers_%d.png", level)
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set xlabel "worst volume error against the reference [%]"
set ylabel "CPU s per simulated s (one thread)"
families = "jolt_it1 jolt_it2 jolt_it5 jolt_it10 jolt_it20 jolt_it40 xpbd_fixed xpbd_auto vbd_it4 vbd_it8 bullet_it1 bullet_it4 bullet_it16 symplectic_auto verlet_auto rk4_auto rk45_tolerance vbd_affine"
titles = "'Jolt, 1 iteration' 'Jolt, 2 iterations' 'Jolt, 5 iterations' 'Jolt, 10 iterations' 'Jolt, 20 iterations' 'Jolt, 40 iterations' 'softbody xpbd, substeps 2..64' 'softbody xpbd, auto' 'softbody vbd, 4 sweeps, substeps 1,2,4' 'softbody vbd, 8 sweeps, substeps 1,2,4' 'Bullet, 1 position iteration' 'Bullet, 4 position iterations' 'Bullet, 16 position iterations' 'softbody symplectic, dt auto' 'softbody verlet, dt auto' 'softbody rk4, dt auto' 'softbody rk45, tolerance 1e-3..1e-6' 'softbody vbd, no coarse level, 1 and 2 sweeps'"
# Jolt in blues (darker: more iterations), softbody in red and black (xpbd), greens (vbd) and purples (the explicit
# methods and rk45), Bullet in oranges
colours = "#9ecae1 #6baed6 #4292c6 #2171b5 #08519c #08306b #e31a1c #000000 #74c476 #238b45 #fdae6b #f16913 #a63603 #bcbddc #9e9ac8 #6a51a3 #3f007d #00441b"
rows(scene, family) = sprintf("< awk -F, '$1==\"%s\" && $4==\"%s\" && $9!=\"inf\"' %s", scene, family, data)
# A level run on the breathing alone (SCENES=breathing bench/run_peers.sh 6) gets the breathing's panel only.
bounce_rows = int(system(sprintf("awk -F, '$1==\"bounce\"' %s | wc -l", data)))
if (bounce_rows > 0) {
  set multiplot layout 1,2 margins 0.06,0.78,0.11,0.9 spacing 0.07 title sprintf("icosphere level %d: CPU cost against volume error (Jolt over dt 1/60 .. 1/1920 s)", level)
  set title "breathing in flight, 1 s (no gravity, no floor, no dampers)"
  unset key
} else {
  set title sprintf("icosphere level %d: CPU cost against volume error (Jolt over dt 1/60 .. 1/1920 s)\nbreathing in flight, 1 s (no gravity, no floor, no dampers)", level)
  set lmargin at screen 0.06
  set rmargin at screen 0.6
  set key at screen 0.995,0.88 right top
}
plot for [i in "1 2 3 4 5 6 7 8 9 10 14 15 16 17 18"] rows("breathing", word(families, i+0)) using 9:8 with linespoints lw 2 lc rgb word(colours, i+0) pt (i+0 < 7 ? 7 : (i+0 < 11 ? 5 : (i+0 < 14 ? 9 : 13))) ps 1 title word(titles, i+0)
if (bounce_rows > 0) {
  set title "bounce, first impact 0-1.2 s"
  set key at screen 0.995,0.88 right top
  plot for [i=1:words(families)] rows("bounce", word(families, i)) using 9:8 with linespoints lw 2 lc rgb word(colours, i) pt (i < 7 ? 7 : (i < 11 ? 5 : (i < 14 ? 9 : 13))) ps 1 title word(titles, i)
  unset multiplot
}

# The breathing's volume over time: the reference, Jolt and Bullet at their defaults and finer, xpbd and vbd.
reset
set terminal pngcairo size 1100,560 font "DejaVu Sans,11"
set output sprintf("peers_breathing_volume_%d.png", level)
set datafile separator ","
set grid
set key outside right top
set xlabel "time [s]"
set ylabel "volume / start volume"
set title sprintf("icosphere level %d: the breathing in flight, volume history", level)
run(name) = sprintf("%d/breathing_%s.csv", level, name)
v0 = real(system(sprintf("awk -F, 'NR == 2 { print $10 }' %s", run("ref"))))
# softbody's CSVs have the volume in column 10, the peers' in column 7
plot run("ref") using 2:($10/v0) with lines lw 3 lc rgb "black" title "softbody rk45 1e-9 (reference)", \
     run("jolt_240_5") using 2:($7/v0) with lines lw 2 lc rgb "#6baed6" title "Jolt 1/240 s, 5 iterations", \
     run("jolt_1920_10") using 2:($7/v0) with lines lw 2 lc rgb "#08306b" title "Jolt 1/1920 s, 10 iterations", \
     run("bullet_240_1") using 2:($7/v0) with lines lw 2 lc rgb "#fdae6b" title "Bullet 1/240 s, 1 position iteration", \
     run("bullet_1920_4") using 2:($7/v0) with lines lw 2 lc rgb "#a63603" title "Bullet 1/1920 s, 4 position iterations", \
     run("xpbd_auto") using 2:($10/v0) with lines lw 2 lc rgb "#e31a1c" title "softbody xpbd auto", \
     run("vbd_1_4") using 2:($10/v0) with lines lw 2 lc rgb "#238b45" title "softbody vbd, 4 sweeps"
