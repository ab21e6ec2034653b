# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
82.937 0.570135 0.570135 "explosion map 256, mirrored (the paper)"
15.469 0.235365 0.235365 "environment map 256 px"
115.681 0.228947 0.228947 "environment map 1024 px"
71.236 0.130023 0.130023 "explosion map 128"
74.652 0.129899 0.119946 "explosion map 512"
78.165 0.129868 0.110650 "explosion map 256"
45.609 0.021177 0.021177 "G-buffer x0.5"
91.863 0.006248 0.006248 "G-buffer x2"
58.983 0.003225 0.003225 "uncovered pixels show the background"
54.672 0.000558 0.000558 "G-buffer RGBA16F"
26.708 0.000100 0.000100 "ray-cast every mirror"
85.621 0.000100 0.000100 "explosion map 256, refined"
183.381 0.000100 0.000100 "hierarchy search"
58.442 0.000100 0.000092 "hierarchy search, no tessellation"
620.016 0.000100 0.000100 "full level 4"
237.761 0.000100 0.000092 "full level 3"
73.573 0.000100 0.000085 "full level 2"
33.859 0.000100 0.000085 "full level 1"
30.971 0.000100 0.000092 "adaptive angle 0.001"
26.361 0.000100 0.000079 "adaptive angle 0.003"
25.676 0.000100 0.000072 "adaptive angle 0.01"
49.639 0.000100 0.000079 "adaptive 0.25 px"
33.825 0.000100 0.000067 "adaptive 0.5 px"
26.569 0.000100 0.000062 "adaptive 1 px"
19.632 0.000100 0.000057 "adaptive 2 px"
18.539 0.000100 0.000085 "search, no tessellation"
EOD
$front << EOD
15.469 0.235365
18.539 0.000100
EOD
set title "checker-sphere at 320x240: 4 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [12.287400:1747.443105]
set yrange [0.000040:0.805337]
set arrow 1 from 21.635, graph 0 to 21.635, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 22 ms, error 0" at 21.635, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
