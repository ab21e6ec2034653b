# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
56.773 0.056048 0.056048 "explosion map 256, mirrored (the paper)"
213.460 0.052331 0.052331 "environment map 1024 px"
43.133 0.052222 0.051704 "environment map 256 px"
60.667 0.009213 0.009213 "uncovered pixels show the background"
59.732 0.008838 0.008499 "explosion map 128"
55.930 0.008832 0.007840 "explosion map 256"
71.055 0.008826 0.007233 "explosion map 512"
64.672 0.007380 0.006672 "G-buffer x0.5"
73.411 0.004198 0.004198 "G-buffer x2"
64.369 0.002175 0.002175 "G-buffer RGBA16F"
258.483 0.002038 0.002038 "full level 3"
72.678 0.002027 0.002007 "ray-cast every mirror"
77.937 0.002027 0.001851 "explosion map 256, refined"
107.407 0.002027 0.001708 "hierarchy search"
97.722 0.002027 0.001575 "hierarchy search, no tessellation"
688.904 0.002027 0.002027 "full level 4"
106.479 0.002027 0.001453 "full level 2"
90.735 0.002027 0.001341 "full level 1"
63.687 0.002027 0.001237 "adaptive angle 0.001"
63.314 0.002027 0.001141 "adaptive angle 0.003"
66.271 0.002027 0.001052 "adaptive angle 0.01"
55.870 0.002027 0.001708 "adaptive 0.25 px"
70.621 0.002027 0.000971 "adaptive 0.5 px"
72.457 0.002027 0.000896 "adaptive 1 px"
62.711 0.002027 0.000826 "adaptive 2 px"
76.146 0.002027 0.000762 "search, no tessellation"
EOD
$front << EOD
43.133 0.052222
55.870 0.002027
EOD
set title "skinned at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [34.261904:1941.593894]
set yrange [0.000540:0.079170]
set arrow 1 from 59.079, graph 0 to 59.079, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 59 ms, error 0" at 59.079, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
