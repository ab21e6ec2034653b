# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
38.302 0.326016 0.326016 "environment map 256 px"
144.210 0.319423 0.319423 "environment map 1024 px"
70.861 0.279752 0.279752 "explosion map 256, mirrored (the paper)"
63.118 0.145579 0.145579 "explosion map 128"
58.170 0.145477 0.134296 "explosion map 256"
60.902 0.145428 0.123887 "explosion map 512"
105.447 0.012870 0.012870 "G-buffer x0.5"
105.086 0.005141 0.005141 "mesh 32x16"
115.738 0.004678 0.004678 "G-buffer x2"
118.655 0.002961 0.002961 "uncovered pixels show the background"
70.307 0.001974 0.001974 "search, no tessellation"
73.695 0.001974 0.001821 "adaptive angle 0.01"
102.750 0.001974 0.001680 "hierarchy search, no tessellation"
93.687 0.001588 0.001550 "adaptive angle 0.003"
79.235 0.001588 0.001430 "adaptive angle 0.001"
95.526 0.001529 0.001319 "G-buffer RGBA16F"
143.033 0.001459 0.001430 "full level 1"
131.392 0.001203 0.001203 "mesh 64x32"
258.142 0.001116 0.001116 "hierarchy search"
107.480 0.001116 0.001110 "explosion map 256, refined"
116.896 0.001116 0.001024 "adaptive 2 px"
112.669 0.001116 0.000945 "adaptive 1 px"
280.043 0.000987 0.000987 "full level 2"
123.743 0.000601 0.000601 "adaptive 0.5 px"
138.358 0.000601 0.000554 "adaptive 0.25 px"
2049.929 0.000601 0.000601 "full level 4"
855.475 0.000601 0.000601 "full level 3"
43.648 0.000601 0.000601 "ray-cast every mirror"
117.854 0.000526 0.000511 "mesh 128x64"
133.359 0.000429 0.000429 "mesh 256x128"
EOD
$front << EOD
38.302 0.326016
43.648 0.000601
117.854 0.000526
133.359 0.000429
EOD
set title "flag at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [30.424685:5777.485937]
set yrange [0.000304:0.460510]
set arrow 1 from 48.504, graph 0 to 48.504, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 49 ms, error 0" at 48.504, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
