"""Tools above the product: benchmarks (bench), precision sweeps (precision), the mpmath oracle (reference) and
the Dask layer (distributed). They import the library and the validation layer; nothing in the library imports
them."""
