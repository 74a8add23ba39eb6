# Wall time per simulated second against error for the issue-13 bounce (bench/run_large_steps.sh): one panel per
# icosphere level, one point (or line over steps) per integrator, Bullet's btSoftBody in black.
set datafile separator ','
set terminal pngcairo size 1500,560 enhanced font 'Sans,10'
set output 'large_steps_bounce.png'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set key outside bottom center horizontal maxrows 2 font ',9'
programs = 'euler symplectic verlet rk4 rk45 implicit newton xpbd'
csv = 'large_steps_bounce.csv'
# Column 15: RMS vertex error over the sampled frames [m]; 9: CPU s per simulated s (one thread); 17: status.
ok(level, name) = (column(1) == level && strcol(3) eq name && strcol(17) eq 'ok')
duration(level) = system(sprintf("awk -F, '$1==%d && $3 ~ /^reference rk45/ {print $2; exit}' %s", level, csv))
set multiplot layout 1,3 title "bounce (k 1000 N/m, c 1 N·s/m, nRT 50 J, 1 kg): error against rk45 (tolerance 1e-8, smooth floor); one thread, this shared 2-core machine"
do for [level in '3 5 6'] {
  set title sprintf('icosphere:%s, %s s simulated', level, duration(level + 0))
  set xlabel 'RMS vertex error over the frames [m]'
  set ylabel 'CPU s per simulated s (one thread)'
  plot for [i = 1:words(programs)] csv using (ok(level + 0, 'softbody '.word(programs, i)) ? $15 : NaN):9 \
         with linespoints lw 2 pt (i + 3) ps 1.4 title word(programs, i), \
       csv using (ok(level + 0, 'bullet btSoftBody') ? $15 : NaN):9 with linespoints lw 2 pt 5 ps 1.6 lc rgb 'black' \
         title 'Bullet btSoftBody 1/60, 1/240 s (own model)', \
       csv using (ok(level + 0, 'bullet btSoftBody') ? $15 : NaN):9:(strcol(6)) with labels offset 0,1 font ',8' notitle
}
unset multiplot
