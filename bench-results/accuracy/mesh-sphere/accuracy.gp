# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
67.361 0.570558 0.570558 "explosion map 256, mirrored (the paper)"
39.802 0.236289 0.236289 "environment map 256 px"
91.415 0.229470 0.229470 "environment map 1024 px"
66.741 0.129830 0.129830 "explosion map 128"
72.417 0.129814 0.119768 "explosion map 512"
59.171 0.129795 0.110485 "explosion map 256"
71.167 0.009590 0.009590 "G-buffer x0.5"
67.274 0.004215 0.004215 "uncovered pixels show the background"
84.731 0.002464 0.002464 "G-buffer x2"
69.464 0.000551 0.000551 "G-buffer RGBA16F"
240.815 0.000100 0.000100 "hierarchy search"
48.027 0.000100 0.000100 "ray-cast every mirror"
86.453 0.000100 0.000100 "mesh 256x128"
76.848 0.000100 0.000092 "mesh 128x64"
63.636 0.000100 0.000085 "mesh 64x32"
69.800 0.000100 0.000079 "mesh 32x16"
79.913 0.000100 0.000072 "explosion map 256, refined"
56.545 0.000100 0.000067 "search, no tessellation"
66.612 0.000100 0.000062 "adaptive 2 px"
75.407 0.000100 0.000057 "adaptive 1 px"
86.596 0.000100 0.000052 "adaptive 0.5 px"
63.275 0.000100 0.000048 "adaptive angle 0.001"
73.549 0.000100 0.000045 "hierarchy search, no tessellation"
116.526 0.000100 0.000085 "adaptive 0.25 px"
56.235 0.000100 0.000041 "adaptive angle 0.01"
56.575 0.000100 0.000038 "adaptive angle 0.003"
697.416 0.000100 0.000100 "full level 4"
253.641 0.000100 0.000092 "full level 3"
100.502 0.000100 0.000041 "full level 2"
62.423 0.000100 0.000035 "full level 1"
EOD
$front << EOD
39.802 0.236289
48.027 0.000100
69.800 0.000100
EOD
set title "mesh-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [31.615507:1965.585821]
set yrange [0.000025:0.805935]
set arrow 1 from 56.829, graph 0 to 56.829, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 57 ms, error 0" at 56.829, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
