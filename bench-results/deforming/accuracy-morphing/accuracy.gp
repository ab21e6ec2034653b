# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
38.556 0.118501 0.118501 "environment map 256 px"
158.847 0.117964 0.117964 "environment map 1024 px"
65.298 0.105911 0.105911 "explosion map 256, mirrored (the paper)"
71.543 0.017095 0.017095 "explosion map 512"
65.799 0.017063 0.015770 "explosion map 256"
48.124 0.017004 0.014548 "explosion map 128"
59.692 0.009387 0.009387 "uncovered pixels show the background"
62.381 0.008998 0.008659 "G-buffer x0.5"
74.804 0.004648 0.004648 "G-buffer x2"
51.838 0.003048 0.003048 "adaptive angle 0.01"
49.423 0.002952 0.002812 "adaptive angle 0.003"
70.631 0.002894 0.002594 "search, no tessellation"
117.329 0.002894 0.002894 "hierarchy search, no tessellation"
50.153 0.002638 0.002393 "adaptive angle 0.001"
67.578 0.002611 0.002207 "G-buffer RGBA16F"
440.151 0.002271 0.002271 "full level 3"
41.239 0.002271 0.002036 "adaptive 1 px"
151.008 0.002271 0.002271 "hierarchy search"
86.075 0.002271 0.002036 "explosion map 256, refined"
51.783 0.002271 0.001879 "adaptive 0.5 px"
67.359 0.002266 0.001733 "adaptive 2 px"
1250.912 0.002260 0.002260 "full level 4"
68.835 0.002260 0.001599 "adaptive 0.25 px"
218.147 0.002228 0.002095 "full level 2"
106.755 0.002149 0.001879 "full level 1"
50.918 0.002133 0.001475 "ray-cast every mirror"
EOD
$front << EOD
38.556 0.118501
41.239 0.002271
50.918 0.002133
EOD
set title "morphing at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [30.626238:3525.549689]
set yrange [0.001044:0.167387]
set arrow 1 from 50.322, graph 0 to 50.322, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 50 ms, error 0" at 50.322, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
