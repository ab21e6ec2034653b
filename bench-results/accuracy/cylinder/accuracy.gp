# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
66.066 0.453381 0.453381 "explosion map 256, mirrored (the paper)"
26.954 0.393120 0.393120 "environment map 256 px"
97.177 0.351596 0.351596 "environment map 1024 px"
63.528 0.245353 0.245353 "explosion map 256"
66.611 0.245104 0.226338 "explosion map 512"
58.676 0.244926 0.208796 "explosion map 128"
56.776 0.006850 0.006850 "G-buffer x0.5"
75.797 0.001614 0.001614 "G-buffer x2"
61.578 0.001387 0.001387 "G-buffer RGBA16F"
58.089 0.000149 0.000149 "uncovered pixels show the background"
64.689 0.000106 0.000106 "adaptive angle 0.001"
29.241 0.000100 0.000100 "ray-cast every mirror"
55.866 0.000100 0.000098 "extrusion solved in 2-D"
91.075 0.000100 0.000090 "explosion map 256, refined"
372.879 0.000100 0.000100 "hierarchy search"
99.663 0.000100 0.000098 "hierarchy search, no tessellation"
1851.966 0.000100 0.000100 "full level 4"
485.905 0.000100 0.000092 "full level 3"
187.639 0.000100 0.000100 "full level 2"
84.052 0.000100 0.000083 "full level 1"
57.182 0.000100 0.000077 "adaptive angle 0.003"
57.753 0.000100 0.000071 "adaptive angle 0.01"
84.430 0.000100 0.000065 "adaptive 0.25 px"
75.763 0.000100 0.000060 "adaptive 0.5 px"
72.361 0.000100 0.000056 "adaptive 1 px"
66.114 0.000100 0.000051 "adaptive 2 px"
49.702 0.000100 0.000090 "search, no tessellation"
EOD
$front << EOD
26.954 0.393120
29.241 0.000100
EOD
set title "cylinder at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [21.410177:5219.549731]
set yrange [0.000036:0.640417]
set arrow 1 from 35.577, graph 0 to 35.577, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 36 ms, error 0" at 35.577, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
