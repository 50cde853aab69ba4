# The distance of one run's history of a column from a reference run's:
# int |q - q_ref| dt / int |q_ref - base| dt over the test's times (the
# reference interpolated linearly in time; base the reference's first
# value unless given), the relative L1 error of a pressure history against
# a finer run's.
#   awk -v col=right_wall_p_Pa [-v base=1e5] -f scripts/lib/history_error.awk REF/history.csv RUN/history.csv
BEGIN { FS = "," }
FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; if (!(col in c)) { print "no column " col > "/dev/stderr"; exit 2 }; file++; next }
file == 1 { n++; rt[n] = $c["time_s"]; rq[n] = $c[col]; if (n == 1 && base == "") base = rq[1]; next }
{
    t = $c["time_s"]; q = $c[col]
    while (k < n - 1 && rt[k + 1] < t) k++
    if (k < 1) k = 1
    ref = rq[k] + (rq[k + 1] - rq[k]) * (t - rt[k]) / (rt[k + 1] - rt[k])
    if (m > 0) { dt = t - tp; num += 0.5 * dt * (abs(q - ref) + ep); den += 0.5 * dt * (abs(ref - base) + dp) }
    ep = abs(q - ref); dp = abs(ref - base); tp = t; m++
}
function abs(x) { return x < 0 ? -x : x }
END { if (den > 0) printf "%.4f\n", num / den }
