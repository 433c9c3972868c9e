# Prints the smallest and the median of a column of numbers sorted in
# ascending order (sort -g), for the interleaved throughput benchmarks.
{ t[NR] = $1 }
END { m = (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2; printf "%s %s", t[1], m }
