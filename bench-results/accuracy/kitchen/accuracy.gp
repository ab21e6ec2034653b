# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
41.639 0.144904 0.144904 "environment map 256 px"
197.211 0.144493 0.144493 "environment map 1024 px"
310.600 0.105977 0.105977 "G-buffer x0.5"
417.182 0.035259 0.035259 "G-buffer x2"
70.989 0.033197 0.033197 "search, no tessellation"
354.225 0.022808 0.022808 "uncovered pixels show the background"
2490.989 0.018869 0.018869 "adaptive angle 0.001"
1824.742 0.017560 0.017406 "adaptive angle 0.003"
1135.691 0.016152 0.016057 "adaptive angle 0.01"
308.353 0.012609 0.012609 "full level 1"
1082.892 0.007176 0.007176 "full level 2"
2501.883 0.007176 0.007176 "full level 3"
2534.027 0.007176 0.006619 "full level 4"
378.030 0.006714 0.006714 "G-buffer RGBA16F"
336.537 0.005472 0.005472 "adaptive 2 px"
440.444 0.004793 0.004793 "adaptive 0.5 px"
566.586 0.004713 0.004421 "adaptive 0.25 px"
365.889 0.004553 0.004079 "adaptive 1 px"
30.502 0.001416 0.001416 "ray-cast every mirror"
EOD
$front << EOD
30.502 0.001416
EOD
set title "kitchen at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [24.228891:7141.857787]
set yrange [0.001002:0.204682]
set arrow 1 from 44.485, graph 0 to 44.485, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 44 ms, error 0" at 44.485, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
