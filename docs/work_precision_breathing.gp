# Work-precision plot of softbody's integrators (written by softbody bench accuracy).
set terminal pngcairo size 960,680 enhanced font 'Sans,11'
set output 'work_precision_breathing.png'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set xlabel 'RMS vertex position error over all frames [m]'
set ylabel 'wall time of the run (stepping only) [s]'
set key outside right top
set title "breathing: 162 vertices, 2 s simulated; reference rk45 fixed step (5th order), dt 1e-05 s"
set arrow from 9.88803e-15, graph 0 to 9.88803e-15, graph 1 nohead dashtype 2 lc rgb 'gray40'
set label 'reference uncertainty' at 9.88803e-15, graph 0.04 offset 0.5,0 font ',9' tc rgb 'gray30'
set xrange [3.29601e-15:*]
plot '-' using 1:2 with linespoints lw 2 pt 4 title 'euler', '-' using 1:2 with linespoints lw 2 pt 5 title 'symplectic', '-' using 1:2 with linespoints lw 2 pt 6 title 'verlet', '-' using 1:2 with linespoints lw 2 pt 7 title 'rk4', '-' using 1:2 with linespoints lw 2 pt 8 title 'rk45', '-' using 1:2 with linespoints lw 2 pt 9 title 'implicit'
2.350611e-01 2.360512e-01
3.132424e-03 4.668159e-01
1.422390e-03 9.722478e-01
6.717429e-04 1.860350e+00
3.259796e-04 3.802482e+00
e
3.755042e-03 1.199990e-02
1.215049e-03 2.495286e-02
4.401942e-04 4.439780e-02
1.804747e-04 6.036603e-02
8.011667e-05 1.207068e-01
3.763266e-05 2.708236e-01
1.819995e-05 5.830335e-01
8.950265e-06 9.232537e-01
4.436952e-06 2.222250e+00
e
2.751564e-03 7.786860e-03
6.950441e-04 1.569414e-02
1.738976e-04 5.418270e-02
4.399524e-05 1.081157e-01
1.099796e-05 1.245859e-01
2.757599e-06 2.447056e-01
6.893801e-07 4.904029e-01
1.724717e-07 9.870188e-01
4.311759e-08 1.975939e+00
1.078138e-08 4.021921e+00
e
3.991016e-04 1.548131e-02
3.029513e-05 2.961263e-02
1.897990e-06 5.944687e-02
1.187766e-07 1.193953e-01
7.609111e-09 2.354804e-01
4.757909e-10 4.857824e-01
2.992505e-11 9.752540e-01
1.873700e-12 1.874174e+00
e
1.064491e-03 3.498541e-02
7.705257e-05 3.007483e-02
8.698550e-06 2.998850e-02
1.630609e-06 3.569733e-02
1.701669e-07 5.592314e-02
1.792884e-08 8.672718e-02
1.885251e-09 1.435672e-01
1.938570e-10 2.346672e-01
1.989105e-11 3.394252e-01
2.027615e-12 5.718855e-01
e
8.006932e-03 9.125830e-02
7.888577e-03 1.140583e-01
7.633743e-03 1.725939e-01
7.141749e-03 2.805597e-01
6.250184e-03 5.697014e-01
4.859128e-03 9.276386e-01
3.294775e-03 1.810231e+00
1.990437e-03 3.377253e+00
e
