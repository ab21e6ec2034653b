# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
29.947 0.236485 0.236485 "environment map 256 px"
78.735 0.229739 0.229739 "environment map 1024 px"
28.970 0.054252 0.054252 "search, no tessellation"
34.494 0.035516 0.035516 "adaptive angle 0.01"
36.525 0.013662 0.013662 "full level 1"
26.372 0.011620 0.011620 "G-buffer x0.5"
33.131 0.008562 0.008562 "adaptive angle 0.003"
53.497 0.006315 0.006315 "adaptive angle 0.001"
49.403 0.005627 0.005627 "G-buffer x2"
38.192 0.004400 0.004400 "adaptive 2 px"
31.138 0.004053 0.004053 "G-buffer RGBA16F"
41.601 0.003460 0.003460 "adaptive 1 px"
61.497 0.003102 0.003102 "full level 2"
47.578 0.002666 0.002666 "adaptive 0.5 px"
156.417 0.002321 0.002321 "full level 3"
61.340 0.001980 0.001980 "adaptive 0.25 px"
378.371 0.001715 0.001715 "full level 4"
28.189 0.000100 0.000100 "ray-cast every mirror"
EOD
$front << EOD
26.372 0.011620
28.189 0.000100
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [20.948313:1066.394176]
set yrange [0.000071:0.334045]
set arrow 1 from 45.630, graph 0 to 45.630, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 46 ms, error 0" at 45.630, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
