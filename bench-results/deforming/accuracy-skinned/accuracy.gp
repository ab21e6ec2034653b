# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
33.897 0.056048 0.056048 "explosion map 256, mirrored (the paper)"
157.996 0.052331 0.052331 "environment map 1024 px"
39.351 0.052222 0.051704 "environment map 256 px"
31.364 0.009213 0.009213 "uncovered pixels show the background"
30.115 0.008838 0.008499 "explosion map 128"
31.900 0.008832 0.007840 "explosion map 256"
40.501 0.008826 0.007233 "explosion map 512"
41.155 0.007380 0.006672 "G-buffer x0.5"
59.497 0.004198 0.004198 "G-buffer x2"
45.413 0.002175 0.002175 "G-buffer RGBA16F"
135.987 0.002038 0.002038 "full level 3"
29.015 0.002027 0.002007 "ray-cast every mirror"
46.709 0.002027 0.001851 "explosion map 256, refined"
54.614 0.002027 0.002007 "hierarchy search"
49.764 0.002027 0.001708 "hierarchy search, no tessellation"
443.710 0.002027 0.002027 "full level 4"
80.056 0.002027 0.001575 "full level 2"
61.548 0.002027 0.001453 "full level 1"
45.698 0.002027 0.001341 "adaptive angle 0.001"
42.480 0.002027 0.001575 "adaptive angle 0.003"
45.338 0.002027 0.001237 "adaptive angle 0.01"
43.112 0.002027 0.001141 "adaptive 0.25 px"
40.554 0.002027 0.001052 "adaptive 0.5 px"
39.929 0.002027 0.000971 "adaptive 1 px"
40.866 0.002027 0.000896 "adaptive 2 px"
51.851 0.002027 0.000826 "search, no tessellation"
EOD
$front << EOD
29.015 0.002027
EOD
set title "skinned at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [23.047559:1250.545012]
set yrange [0.000585:0.079170]
set arrow 1 from 47.109, graph 0 to 47.109, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 47 ms, error 0" at 47.109, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
