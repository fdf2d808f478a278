# A torus of m x n quads (awk -v m=M -v n=N), each cut into two triangles, as OBJ with 17-digit
# coordinates: the benchmarks' closed mesh of valence 6 (saved_files_bench.sh, lods_bench.sh).
BEGIN {
  R = 1.0; r = 0.35; pi = atan2(0, -1)
  for (i = 0; i < m; i++) for (j = 0; j < n; j++) {
    u = 2 * pi * i / m; v = 2 * pi * j / n
    printf "v %.17g %.17g %.17g\n", (R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v)
  }
  for (i = 0; i < m; i++) for (j = 0; j < n; j++) {
    a = i * n + j + 1; b = ((i + 1) % m) * n + j + 1; c = ((i + 1) % m) * n + (j + 1) % n + 1; d = i * n + (j + 1) % n + 1
    printf "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d
  }
}
