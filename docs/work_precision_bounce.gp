# Work-precision plot of softbody's integrators (written by softbody bench accuracy).
set terminal pngcairo size 960,680 enhanced font 'Sans,11'
set output 'work_precision_bounce.png'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set xlabel 'RMS vertex position error over all frames [m]'
set ylabel 'wall time of the run (stepping only) [s]'
set key outside right top
set title "bounce: 642 vertices, 1 s simulated; reference rk45 fixed step (5th order), dt 1e-05 s"
set arrow from 0.00498582, graph 0 to 0.00498582, graph 1 nohead dashtype 2 lc rgb 'gray40'
set label 'reference uncertainty' at 0.00498582, graph 0.04 offset 0.5,0 font ',9' tc rgb 'gray30'
set xrange [0.00107625:*]
plot '-' using 1:2 with linespoints lw 2 pt 4 title 'euler', '-' using 1:2 with linespoints lw 2 pt 5 title 'symplectic', '-' using 1:2 with linespoints lw 2 pt 6 title 'verlet', '-' using 1:2 with linespoints lw 2 pt 7 title 'rk4', '-' using 1:2 with linespoints lw 2 pt 8 title 'rk45', '-' using 1:2 with linespoints lw 2 pt 9 title 'implicit'
6.562985e-02 1.172007e-01
4.623083e-02 4.146598e-01
3.233405e-02 5.083948e-01
2.749930e-02 9.876163e-01
1.330822e-02 1.892414e+00
4.462535e-03 3.994304e+00
e
5.901415e-02 6.029293e-02
6.572255e-02 1.191563e-01
5.957923e-02 2.383140e-01
5.534001e-02 8.073069e-01
5.438783e-02 1.212912e+00
4.987990e-02 1.924483e+00
3.700100e-02 4.668748e+00
e
3.087637e-02 1.442029e-01
2.930185e-02 2.783163e-01
2.510733e-02 5.481243e-01
4.837324e-03 1.058485e+00
3.228742e-03 2.088846e+00
e
7.204155e-02 1.192773e-01
5.082014e-02 2.398212e-01
3.697897e-02 4.790715e-01
3.280398e-02 9.639058e-01
2.314449e-02 1.920908e+00
4.718439e-03 3.781311e+00
e
6.041092e-02 1.215102e-01
5.833132e-02 1.473991e-01
4.801958e-02 1.868810e-01
4.848013e-02 2.535872e-01
2.729872e-02 3.617783e-01
2.895451e-02 5.314700e-01
2.158294e-02 8.235835e-01
7.736195e-03 1.263765e+00
4.188223e-03 2.020081e+00
e
5.925497e-02 4.147380e-01
4.291348e-02 5.565833e-01
5.833571e-02 7.509613e-01
5.836203e-02 1.098709e+00
4.659773e-02 1.697286e+00
4.907115e-02 2.885649e+00
e
