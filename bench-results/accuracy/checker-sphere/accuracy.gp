# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
74.340 0.236146 0.236146 "environment map 256 px"
172.715 0.229400 0.229400 "environment map 1024 px"
68.751 0.065691 0.065691 "search, no tessellation"
81.533 0.057582 0.057582 "adaptive angle 0.01"
84.736 0.041305 0.041305 "adaptive angle 0.003"
95.846 0.037097 0.037097 "adaptive angle 0.001"
82.426 0.031482 0.031482 "adaptive 2 px"
102.177 0.021811 0.021811 "G-buffer RGBA16F"
74.836 0.021805 0.020121 "G-buffer x0.5"
94.475 0.021782 0.018561 "adaptive 1 px"
139.133 0.021770 0.020121 "G-buffer x2"
76.936 0.018982 0.017123 "full level 1"
106.736 0.013854 0.013854 "adaptive 0.5 px"
135.945 0.008070 0.008070 "adaptive 0.25 px"
124.383 0.005522 0.005522 "full level 2"
282.416 0.001560 0.001560 "full level 3"
915.551 0.000680 0.000680 "full level 4"
EOD
$front << EOD
68.751 0.065691
74.836 0.021805
76.936 0.018982
106.736 0.013854
124.383 0.005522
282.416 0.001560
915.551 0.000680
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key bottom left box opaque
set xrange [54.610747:2580.373904]
set yrange [0.000481:0.333566]
set arrow 1 from 74.316, graph 0 to 74.316, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 74 ms, error 0" at 74.316, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
