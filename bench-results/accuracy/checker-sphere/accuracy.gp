# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
32.874 0.236485 0.236485 "environment map 256 px"
87.502 0.229739 0.229739 "environment map 1024 px"
32.504 0.009339 0.009339 "G-buffer x0.5"
32.060 0.003460 0.003460 "uncovered pixels show the background"
54.747 0.002467 0.002467 "G-buffer x2"
34.360 0.000628 0.000628 "G-buffer RGBA16F"
29.448 0.000100 0.000100 "ray-cast every mirror"
442.600 0.000100 0.000100 "full level 4"
196.794 0.000100 0.000100 "full level 3"
72.747 0.000100 0.000100 "full level 2"
43.169 0.000100 0.000092 "full level 1"
51.072 0.000100 0.000085 "adaptive angle 0.001"
41.688 0.000100 0.000079 "adaptive angle 0.003"
43.757 0.000100 0.000072 "adaptive angle 0.01"
71.921 0.000100 0.000067 "adaptive 0.25 px"
62.689 0.000100 0.000062 "adaptive 0.5 px"
44.582 0.000100 0.000057 "adaptive 1 px"
46.882 0.000100 0.000052 "adaptive 2 px"
39.723 0.000100 0.000067 "search, no tessellation"
EOD
$front << EOD
29.448 0.000100
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [23.391669:1247.415867]
set yrange [0.000037:0.334045]
set arrow 1 from 49.777, graph 0 to 49.777, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 50 ms, error 0" at 49.777, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
set label 2 "mismatch under 0.0001 (exact included) is drawn on this line" at graph 0.99, first 0.000100 right offset 0, 0.8 font ',8' textcolor rgb '#444444' noenhanced
set terminal pngcairo size 1100,750 font ',10'
set output "accuracy.png"
plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title 'Pareto front', \
     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \
     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle
set terminal svg size 1100,750 dynamic font ',10'
set output "accuracy.svg"
plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title 'Pareto front', \
     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \
     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle
unset output
