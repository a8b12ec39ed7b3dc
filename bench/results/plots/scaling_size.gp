set terminal pngcairo size 700,460 font 'Sans,10'
set output 'bench/results/plots/scaling_size.png'
set logscale xy
set key top left
set xlabel 'vertices'
set ylabel 'seconds'
plot 'bench/results/plots/scaling_size_greedy.dat' using 1:2 with linespoints title 'greedy layout', \
     'bench/results/plots/scaling_size_voronoi-C.dat' using 1:2 with linespoints title 'Voronoi layout (C)', \
     'bench/results/plots/scaling_size_voronoi-C.dat' using 1:3 with linespoints dt 2 title 'one Dijkstra sweep'
