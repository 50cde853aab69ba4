# The chamber block's distortion (cases/chamber_detonation.yaml's solid
# probes): the largest displacement of its front (charge-side) and back
# corners relative to its centre over the run, in micrometres, "front back".
# A rigid motion gives 0 0.
#   awk -f scripts/lib/corner_distortion.awk OUT/history.csv
BEGIN { FS = "," }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    cx = $col["block_centre_dx_m"]; cy = $col["block_centre_dy_m"]
    fx = $col["front_corner_dx_m"] - cx; fy = $col["front_corner_dy_m"] - cy
    bx = $col["back_corner_dx_m"] - cx; by = $col["back_corner_dy_m"] - cy
    f = sqrt(fx * fx + fy * fy); b = sqrt(bx * bx + by * by)
    if (f > front) front = f
    if (b > back) back = b
}
END { printf "%.1f %.1f\n", 1e6 * front, 1e6 * back }
