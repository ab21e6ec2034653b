# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
408.634 0.322676 0.322676 "explosion map 256, mirrored (the paper)"
312.555 0.302073 0.297668 "explosion map 256"
315.418 0.269641 0.269641 "explosion map 512"
286.078 0.265170 0.248743 "explosion map 128"
420.690 0.180844 0.180844 "G-buffer x0.5"
939.035 0.161932 0.161932 "environment map 1024 px"
82.850 0.160597 0.160597 "environment map 256 px"
690.617 0.082751 0.082751 "G-buffer x2"
230.747 0.079580 0.079580 "search, no tessellation"
325.047 0.052114 0.052114 "hierarchy search, no tessellation"
6647.326 0.029172 0.029172 "adaptive angle 0.001"
2955.637 0.025347 0.025347 "adaptive angle 0.01"
4451.214 0.025324 0.023382 "adaptive angle 0.003"
568.309 0.019782 0.019782 "uncovered pixels show the background"
528.184 0.014563 0.014563 "full level 1"
4472.804 0.013303 0.013303 "full level 4"
5603.077 0.013303 0.012272 "full level 3"
2867.413 0.013303 0.012272 "full level 2"
645.138 0.010619 0.010619 "G-buffer RGBA16F"
1268.791 0.004593 0.004593 "hierarchy search"
407.021 0.003942 0.003942 "adaptive 1 px"
989.730 0.002673 0.002673 "adaptive 0.25 px"
560.466 0.002640 0.002465 "adaptive 0.5 px"
728.012 0.002640 0.002274 "adaptive 2 px"
659.245 0.001989 0.001989 "explosion map 256, refined"
31.893 0.000674 0.000674 "ray-cast every mirror"
EOD
$front << EOD
31.893 0.000674
EOD
set title "kitchen at 320x240: 4 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [25.333748:18734.710004]
set yrange [0.000477:0.455792]
set arrow 1 from 36.589, graph 0 to 36.589, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 37 ms, error 0" at 36.589, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
