# Google Benchmark programs.
