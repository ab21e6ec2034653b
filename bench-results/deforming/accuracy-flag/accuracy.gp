# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
60.762 0.326016 0.326016 "environment map 256 px"
269.113 0.319423 0.319423 "environment map 1024 px"
123.857 0.279752 0.279752 "explosion map 256, mirrored (the paper)"
83.452 0.145579 0.145579 "explosion map 128"
103.250 0.145477 0.134296 "explosion map 256"
113.827 0.145428 0.123887 "explosion map 512"
170.832 0.012870 0.012870 "G-buffer x0.5"
103.583 0.005141 0.005141 "mesh 32x16"
171.985 0.004678 0.004678 "G-buffer x2"
107.776 0.002961 0.002961 "uncovered pixels show the background"
92.441 0.001974 0.001974 "search, no tessellation"
124.336 0.001974 0.001821 "adaptive angle 0.01"
142.971 0.001974 0.001680 "hierarchy search, no tessellation"
112.559 0.001588 0.001550 "adaptive angle 0.003"
116.412 0.001588 0.001430 "adaptive angle 0.001"
165.627 0.001529 0.001319 "G-buffer RGBA16F"
163.231 0.001459 0.001217 "full level 1"
105.579 0.001203 0.001122 "mesh 64x32"
358.599 0.001116 0.001116 "hierarchy search"
113.479 0.001116 0.001035 "explosion map 256, refined"
127.604 0.001116 0.000955 "adaptive 2 px"
159.642 0.001116 0.000881 "adaptive 1 px"
468.461 0.000987 0.000987 "full level 2"
169.696 0.000601 0.000601 "adaptive 0.5 px"
197.013 0.000601 0.000554 "adaptive 0.25 px"
3406.993 0.000601 0.000601 "full level 4"
1150.662 0.000601 0.000601 "full level 3"
51.119 0.000601 0.000601 "ray-cast every mirror"
111.944 0.000526 0.000511 "mesh 128x64"
137.360 0.000429 0.000429 "mesh 256x128"
EOD
$front << EOD
51.119 0.000601
111.944 0.000526
137.360 0.000429
EOD
set title "flag at 640x480: 8 poses, 0 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [40.604916:9602.212270]
set yrange [0.000304:0.460510]
set arrow 1 from 56.667, graph 0 to 56.667, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 57 ms, error 0" at 56.667, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
