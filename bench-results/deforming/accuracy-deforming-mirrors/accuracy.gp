# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
83.912 0.142560 0.142560 "environment map 256 px"
536.593 0.141672 0.141672 "environment map 1024 px"
94.882 0.018041 0.018041 "G-buffer x0.5"
102.148 0.009167 0.009167 "G-buffer RGBA16F"
106.506 0.008614 0.008456 "G-buffer x2"
84.143 0.000252 0.000252 "ray-cast every mirror"
86.851 0.000252 0.000232 "explosion map 256, refined"
94.176 0.000252 0.000214 "explosion map 256, mirrored (the paper)"
112.974 0.000252 0.000198 "explosion map 512"
94.332 0.000252 0.000182 "explosion map 256"
92.653 0.000252 0.000168 "explosion map 128"
104.471 0.000252 0.000155 "hierarchy search"
97.416 0.000252 0.000143 "hierarchy search, no tessellation"
108.255 0.000252 0.000132 "uncovered pixels show the background"
106.154 0.000252 0.000122 "full level 4"
92.508 0.000252 0.000112 "full level 3"
102.159 0.000252 0.000104 "full level 2"
106.671 0.000252 0.000096 "full level 1"
107.386 0.000252 0.000088 "adaptive angle 0.001"
105.887 0.000252 0.000081 "adaptive angle 0.003"
106.367 0.000252 0.000075 "adaptive angle 0.01"
105.786 0.000252 0.000069 "adaptive 0.25 px"
107.839 0.000252 0.000064 "adaptive 0.5 px"
121.738 0.000252 0.000059 "adaptive 1 px"
92.160 0.000252 0.000054 "adaptive 2 px"
109.229 0.000252 0.000050 "search, no tessellation"
EOD
$front << EOD
83.912 0.142560
84.143 0.000252
EOD
set title "deforming-mirrors at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [53.145848:1512.324263]
set yrange [0.000035:0.201371]
set arrow 1 from 66.907, graph 0 to 66.907, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 67 ms, error 0" at 66.907, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
