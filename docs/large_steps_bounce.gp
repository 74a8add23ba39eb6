# Wall time per simulated second against error for the issue-13 bounce (bench/run_large_steps.sh): one panel per
# icosphere level, one point (or line over steps) per integrator and floor contact, Bullet's btSoftBody in black.
set datafile separator ','
set terminal pngcairo size 1800,600 enhanced font 'Sans,10'
set output 'large_steps_bounce.png'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set linetype 8 lc rgb 'dark-magenta'
set linetype 9 lc rgb 'sienna4'
set linetype 10 lc rgb 'dark-green'
# The series: integrator and floor contact, word by word.
names    = 'euler symplectic symplectic verlet rk4 rk45 implicit newton newton xpbd'
contacts = 'smooth smooth friction smooth smooth smooth friction friction smooth smooth'
csv = 'large_steps_bounce.csv'
# Columns: 1 level, 3 program, 5 contact, 6 step, 9 CPU s per simulated s (one thread), 15 RMS vertex error over
# the sampled frames [m], 17 status.
ok(level, program, contact) = (column(1) == level && strcol(3) eq program && strcol(5) eq contact && strcol(17) eq 'ok')
duration(level) = system(sprintf("awk -F, '$1==%d && $3 ~ /^reference rk45/ {print $2; exit}' %s", level, csv))
levels = system(sprintf("tail -n +2 %s | cut -d, -f1 | sort -nu | tr '\\n' ' '", csv))
set xrange [1e-5:10]
set yrange [1e-3:1e3]
set multiplot layout 1,words(levels) title "bounce (k 1000 N/m, c 1 N s/m, nRT 50 J, 1 kg): error against rk45 at tolerance 1e-8 (smooth floor); CPU time on one thread of this shared 2-core machine"
do for [l = 1:words(levels)] {
  level = word(levels, l)
  if (l == 1) { set key inside left bottom vertical font ',8' } else { unset key }  # level 3 has room there
  set title sprintf('icosphere:%s, first %s s', level, duration(level + 0))
  set xlabel 'RMS vertex error over the frames [m]'
  set ylabel 'CPU s per simulated s'
  plot for [i = 1:words(names)] csv \
         using (ok(level + 0, 'softbody '.word(names, i), word(contacts, i)) ? $15 : NaN):9 \
         with linespoints lw 2 pt (i + 3) ps 1.4 title word(names, i).' ('.word(contacts, i).')', \
       csv using (ok(level + 0, 'bullet btSoftBody', 'bullet SDF_RS') ? $15 : NaN):9 \
         with linespoints lw 3 pt 5 ps 1.6 lc rgb 'black' title 'Bullet btSoftBody (own model)', \
       csv using (ok(level + 0, 'bullet btSoftBody', 'bullet SDF_RS') ? $15 : NaN):9:(strcol(6)) \
         with labels offset 0,1 font ',8' notitle, \
       csv using (column(1) == level + 0 && (strcol(3) eq 'softbody newton' || strcol(3) eq 'softbody implicit') && \
                  strcol(17) eq 'ok' ? $15 : NaN):9:(strcol(6)) with labels offset 0,-1 font ',8' notitle
}
unset multiplot
