//! Benchmarks behind `fixedfunc bench`.
