# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
63.763 0.570566 0.570566 "explosion map 256, mirrored (the paper)"
36.613 0.236485 0.236485 "environment map 256 px"
109.277 0.229739 0.229739 "environment map 1024 px"
52.065 0.129935 0.129935 "explosion map 128"
66.724 0.129914 0.119865 "explosion map 512"
56.199 0.129906 0.110575 "explosion map 256"
38.069 0.009325 0.009325 "G-buffer x0.5"
43.461 0.003460 0.003460 "uncovered pixels show the background"
71.735 0.002463 0.002463 "G-buffer x2"
45.413 0.000628 0.000628 "G-buffer RGBA16F"
39.444 0.000100 0.000100 "ray-cast every mirror"
60.768 0.000100 0.000092 "explosion map 256, refined"
191.853 0.000100 0.000100 "hierarchy search"
60.611 0.000100 0.000085 "hierarchy search, no tessellation"
529.828 0.000100 0.000100 "full level 4"
253.866 0.000100 0.000092 "full level 3"
99.854 0.000100 0.000100 "full level 2"
60.777 0.000100 0.000079 "full level 1"
63.298 0.000100 0.000072 "adaptive angle 0.001"
58.755 0.000100 0.000067 "adaptive angle 0.003"
54.332 0.000100 0.000062 "adaptive angle 0.01"
91.088 0.000100 0.000057 "adaptive 0.25 px"
75.269 0.000100 0.000052 "adaptive 0.5 px"
60.095 0.000100 0.000048 "adaptive 1 px"
58.861 0.000100 0.000045 "adaptive 2 px"
51.166 0.000100 0.000057 "search, no tessellation"
EOD
$front << EOD
36.613 0.236485
38.069 0.009325
39.444 0.000100
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [29.082562:1493.259150]
set yrange [0.000032:0.805946]
set arrow 1 from 60.163, graph 0 to 60.163, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 60 ms, error 0" at 60.163, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
