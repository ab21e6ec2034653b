# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
141.815 0.283467 0.283467 "search, no tessellation"
78.627 0.212714 0.212714 "environment map 256 px"
267.743 0.209506 0.209506 "environment map 1024 px"
650.392 0.082100 0.082100 "full level 1"
203.382 0.047075 0.047075 "adaptive angle 0.01"
209.232 0.033093 0.033093 "adaptive angle 0.003"
209.504 0.023130 0.023130 "adaptive angle 0.001"
2419.830 0.017210 0.017210 "full level 2"
4033.838 0.017210 0.015876 "full level 3"
4141.496 0.017210 0.014646 "full level 4"
193.728 0.014622 0.014622 "adaptive 2 px"
205.377 0.006774 0.006774 "G-buffer x0.5"
211.799 0.006771 0.006249 "adaptive 1 px"
230.439 0.006771 0.005765 "G-buffer x2"
209.608 0.006766 0.005318 "G-buffer RGBA16F"
213.755 0.004467 0.004467 "adaptive 0.5 px"
233.819 0.002315 0.002315 "adaptive 0.25 px"
EOD
$front << EOD
78.627 0.212714
193.728 0.014622
205.377 0.006774
209.608 0.006766
213.755 0.004467
233.819 0.002315
EOD
set title "teapot-table at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key bottom left box opaque
set xrange [62.455748:11672.320691]
set yrange [0.001639:0.400408]
set arrow 1 from 96.929, graph 0 to 96.929, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 97 ms, error 0" at 96.929, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
