# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
351.538 0.321996 0.321996 "explosion map 256, mirrored (the paper)"
273.472 0.276454 0.276454 "explosion map 512"
254.233 0.269088 0.255028 "explosion map 256"
227.514 0.245940 0.235263 "explosion map 128"
82.757 0.144904 0.144904 "environment map 256 px"
404.018 0.144493 0.144493 "environment map 1024 px"
528.647 0.104660 0.104660 "G-buffer x0.5"
473.469 0.054708 0.054708 "hierarchy search, no tessellation"
731.583 0.035259 0.035259 "G-buffer x2"
149.099 0.033197 0.033197 "search, no tessellation"
632.274 0.022808 0.022808 "uncovered pixels show the background"
4809.469 0.018869 0.018869 "adaptive angle 0.001"
3708.086 0.017560 0.017406 "adaptive angle 0.003"
2600.536 0.016152 0.016057 "adaptive angle 0.01"
778.398 0.012609 0.012609 "full level 1"
5441.515 0.007011 0.007011 "full level 4"
5559.919 0.007011 0.006468 "full level 3"
2545.430 0.007011 0.007011 "full level 2"
2431.763 0.006811 0.006468 "hierarchy search"
670.731 0.006284 0.006284 "G-buffer RGBA16F"
844.091 0.005472 0.005472 "adaptive 2 px"
1005.794 0.004793 0.004793 "adaptive 0.5 px"
883.362 0.004553 0.004421 "adaptive 1 px"
995.892 0.004548 0.004079 "adaptive 0.25 px"
459.497 0.003467 0.003467 "explosion map 256, refined"
36.541 0.001416 0.001416 "ray-cast every mirror"
EOD
$front << EOD
36.541 0.001416
EOD
set title "kitchen at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [29.025628:15669.979872]
set yrange [0.001002:0.454831]
set arrow 1 from 102.622, graph 0 to 102.622, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 103 ms, error 0" at 102.622, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
