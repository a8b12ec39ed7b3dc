set terminal pngcairo size 700,460 font 'Sans,10'
set output 'bench/results/plots/scaling_anchors.png'
set logscale xy
set key top left
set xlabel 'anchors'
set ylabel 'seconds'
plot 'bench/results/plots/scaling_anchors_greedy.dat' using 1:2 with linespoints title 'greedy layout', \
     'bench/results/plots/scaling_anchors_voronoi-C.dat' using 1:2 with linespoints title 'Voronoi layout (C)', \
     'bench/results/plots/scaling_anchors_voronoi-C.dat' using 1:3 with linespoints dt 2 title 'one Dijkstra sweep'
