# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
27.626 0.236485 0.236485 "environment map 256 px"
77.646 0.229739 0.229739 "environment map 1024 px"
27.186 0.054252 0.054252 "search, no tessellation"
34.462 0.035516 0.035516 "adaptive angle 0.01"
35.775 0.013662 0.013662 "full level 1"
26.257 0.011620 0.011620 "G-buffer x0.5"
35.407 0.008562 0.008562 "adaptive angle 0.003"
36.128 0.006315 0.006315 "adaptive angle 0.001"
49.599 0.005627 0.005627 "G-buffer x2"
35.185 0.004400 0.004400 "adaptive 2 px"
30.417 0.004053 0.004053 "G-buffer RGBA16F"
37.832 0.003460 0.003460 "adaptive 1 px"
57.435 0.003102 0.003102 "full level 2"
47.094 0.002666 0.002666 "adaptive 0.5 px"
150.985 0.002321 0.002321 "full level 3"
55.628 0.001980 0.001980 "adaptive 0.25 px"
340.059 0.001715 0.001715 "full level 4"
EOD
$front << EOD
26.257 0.011620
30.417 0.004053
37.832 0.003460
47.094 0.002666
55.628 0.001980
340.059 0.001715
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key bottom left box opaque
set xrange [20.856427:958.416890]
set yrange [0.001214:0.334045]
set arrow 1 from 45.339, graph 0 to 45.339, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 45 ms, error 0" at 45.339, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
