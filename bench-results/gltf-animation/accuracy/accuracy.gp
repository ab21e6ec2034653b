# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
33.238 0.085280 0.085280 "explosion map 256, mirrored (the paper)"
28.841 0.047861 0.047861 "environment map 256 px"
144.277 0.047322 0.047322 "environment map 1024 px"
35.165 0.014377 0.014377 "explosion map 512"
31.062 0.014361 0.013263 "explosion map 256"
32.821 0.014240 0.012235 "explosion map 128"
37.780 0.011686 0.011287 "G-buffer x0.5"
35.048 0.006566 0.006566 "uncovered pixels show the background"
47.068 0.005281 0.005281 "G-buffer x2"
44.285 0.002497 0.002497 "adaptive angle 0.01"
41.307 0.002371 0.002304 "adaptive 2 px"
66.862 0.002333 0.002125 "hierarchy search, no tessellation"
55.174 0.002333 0.001961 "search, no tessellation"
38.536 0.002177 0.001809 "G-buffer RGBA16F"
38.480 0.002170 0.001668 "full level 1"
37.459 0.002099 0.001539 "adaptive 1 px"
79.586 0.002099 0.001809 "hierarchy search"
45.983 0.002099 0.001420 "explosion map 256, refined"
36.712 0.002082 0.001310 "adaptive angle 0.003"
44.875 0.002056 0.001208 "adaptive 0.25 px"
43.371 0.002036 0.001115 "full level 2"
45.199 0.002013 0.001028 "adaptive angle 0.001"
41.468 0.001990 0.000949 "adaptive 0.5 px"
127.743 0.001955 0.001668 "full level 4"
74.133 0.001950 0.001539 "full level 3"
22.413 0.001853 0.001420 "ray-cast every mirror"
EOD
$front << EOD
22.413 0.001853
EOD
set title "animated at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [17.803124:406.628639]
set yrange [0.000672:0.120462]
set arrow 1 from 48.495, graph 0 to 48.495, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 48 ms, error 0" at 48.495, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
