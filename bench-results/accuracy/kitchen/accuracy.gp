# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
41.190 0.144904 0.144904 "environment map 256 px"
200.092 0.144493 0.144493 "environment map 1024 px"
381.063 0.104660 0.104660 "G-buffer x0.5"
290.714 0.054708 0.054708 "hierarchy search, no tessellation"
506.647 0.035259 0.035259 "G-buffer x2"
74.540 0.033197 0.033197 "search, no tessellation"
407.515 0.022808 0.022808 "uncovered pixels show the background"
3258.991 0.018869 0.018869 "adaptive angle 0.001"
2474.667 0.017560 0.017406 "adaptive angle 0.003"
1512.872 0.016152 0.016057 "adaptive angle 0.01"
404.642 0.012609 0.012609 "full level 1"
1590.003 0.007011 0.007011 "full level 2"
3521.629 0.007011 0.007011 "full level 3"
3343.446 0.007011 0.006468 "full level 4"
1363.228 0.006811 0.006468 "hierarchy search"
431.192 0.006284 0.006284 "G-buffer RGBA16F"
405.578 0.005472 0.005472 "adaptive 2 px"
569.638 0.004793 0.004793 "adaptive 0.5 px"
470.563 0.004553 0.004421 "adaptive 1 px"
724.540 0.004548 0.004079 "adaptive 0.25 px"
26.032 0.001416 0.001416 "ray-cast every mirror"
EOD
$front << EOD
26.032 0.001416
EOD
set title "kitchen at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [20.677681:9925.299840]
set yrange [0.001002:0.204682]
set arrow 1 from 46.420, graph 0 to 46.420, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 46 ms, error 0" at 46.420, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
