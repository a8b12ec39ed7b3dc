set terminal pngcairo size 900,420 font 'Sans,10'
set output 'bench/results/plots/e_ang.png'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set datafile missing '?'
set key outside right top noenhanced
set ylabel 'E_ang'
set xtics rotate by -20

plot 'bench/results/plots/e_ang.dat' using 2:xtic(1) title 'greedy (Kraevoy and Sheffer)', '' using 3 title 'Voronoi E1', '' using 4 title 'Voronoi C'
