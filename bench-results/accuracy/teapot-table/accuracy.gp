# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
56.941 0.212915 0.212915 "environment map 256 px"
189.416 0.209707 0.209707 "environment map 1024 px"
94.872 0.161309 0.161309 "explosion map 256, mirrored (the paper)"
104.505 0.046757 0.046757 "explosion map 512"
87.699 0.046743 0.043133 "explosion map 256"
107.105 0.046656 0.039790 "explosion map 128"
130.430 0.004204 0.004204 "G-buffer x0.5"
155.894 0.000649 0.000649 "G-buffer x2"
140.211 0.000474 0.000474 "uncovered pixels show the background"
151.808 0.000340 0.000340 "G-buffer RGBA16F"
478.739 0.000167 0.000167 "hierarchy search, no tessellation"
239.918 0.000167 0.000167 "search, no tessellation"
171.378 0.000159 0.000154 "adaptive angle 0.01"
186.540 0.000159 0.000142 "adaptive angle 0.003"
167.397 0.000156 0.000131 "adaptive 2 px"
161.578 0.000117 0.000117 "adaptive angle 0.001"
503.914 0.000100 0.000100 "hierarchy search"
140.194 0.000100 0.000100 "explosion map 256, refined"
64.074 0.000100 0.000100 "ray-cast every mirror"
3653.042 0.000100 0.000100 "full level 4"
3077.977 0.000100 0.000092 "full level 3"
1642.183 0.000100 0.000100 "full level 2"
502.982 0.000100 0.000092 "full level 1"
249.796 0.000100 0.000100 "adaptive 0.25 px"
195.584 0.000100 0.000092 "adaptive 0.5 px"
209.500 0.000100 0.000085 "adaptive 1 px"
EOD
$front << EOD
56.941 0.212915
64.074 0.000100
EOD
set title "teapot-table at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [45.229744:10295.669885]
set yrange [0.000060:0.300750]
set arrow 1 from 98.866, graph 0 to 98.866, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 99 ms, error 0" at 98.866, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
