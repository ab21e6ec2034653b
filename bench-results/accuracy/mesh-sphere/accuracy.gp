# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
35.188 0.236289 0.236289 "environment map 256 px"
88.205 0.229470 0.229470 "environment map 1024 px"
67.532 0.009590 0.009590 "G-buffer x0.5"
62.680 0.004215 0.004215 "uncovered pixels show the background"
81.102 0.002464 0.002464 "G-buffer x2"
65.445 0.000551 0.000551 "G-buffer RGBA16F"
38.277 0.000100 0.000100 "ray-cast every mirror"
73.202 0.000100 0.000100 "mesh 256x128"
55.715 0.000100 0.000092 "mesh 128x64"
52.774 0.000100 0.000085 "mesh 64x32"
55.980 0.000100 0.000079 "mesh 32x16"
175.602 0.000100 0.000100 "hierarchy search"
64.335 0.000100 0.000072 "hierarchy search, no tessellation"
652.634 0.000100 0.000100 "full level 4"
239.186 0.000100 0.000092 "full level 3"
96.680 0.000100 0.000085 "full level 2"
61.231 0.000100 0.000067 "full level 1"
62.696 0.000100 0.000062 "adaptive angle 0.001"
53.891 0.000100 0.000057 "adaptive angle 0.003"
53.421 0.000100 0.000052 "adaptive angle 0.01"
110.349 0.000100 0.000092 "adaptive 0.25 px"
83.464 0.000100 0.000048 "adaptive 0.5 px"
72.369 0.000100 0.000045 "adaptive 1 px"
63.051 0.000100 0.000041 "adaptive 2 px"
48.395 0.000100 0.000038 "search, no tessellation"
EOD
$front << EOD
35.188 0.236289
38.277 0.000100
55.980 0.000100
EOD
set title "mesh-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [27.950701:1839.373379]
set yrange [0.000027:0.333767]
set arrow 1 from 54.428, graph 0 to 54.428, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 54 ms, error 0" at 54.428, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
