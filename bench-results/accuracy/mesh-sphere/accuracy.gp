# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
35.828 0.236289 0.236289 "environment map 256 px"
77.792 0.229470 0.229470 "environment map 1024 px"
40.093 0.051797 0.051797 "search, no tessellation"
43.408 0.036284 0.036284 "adaptive angle 0.01"
54.305 0.012967 0.012967 "G-buffer x0.5"
50.804 0.012312 0.011962 "full level 1"
43.115 0.010586 0.010586 "adaptive angle 0.003"
54.482 0.007684 0.007684 "adaptive angle 0.001"
69.095 0.005710 0.005710 "G-buffer x2"
53.129 0.005057 0.005057 "G-buffer RGBA16F"
60.678 0.004977 0.004665 "adaptive 2 px"
51.331 0.004683 0.004303 "mesh 32x16"
55.743 0.004381 0.003970 "mesh 64x32"
73.322 0.004230 0.003662 "mesh 256x128"
63.372 0.004215 0.003378 "mesh 128x64"
61.603 0.004215 0.003116 "adaptive 1 px"
80.800 0.004107 0.002875 "full level 2"
202.578 0.003591 0.003591 "full level 3"
71.494 0.003488 0.002652 "adaptive 0.5 px"
495.785 0.003275 0.003275 "full level 4"
87.670 0.002914 0.002446 "adaptive 0.25 px"
38.328 0.000100 0.000100 "ray-cast every mirror"
EOD
$front << EOD
35.828 0.236289
38.328 0.000100
EOD
set title "mesh-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [28.459499:1397.312813]
set yrange [0.000071:0.333767]
set arrow 1 from 47.487, graph 0 to 47.487, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 47 ms, error 0" at 47.487, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
