"""Programs installed by make install: pecplas_sweep (as pecplas-sweep; one file, standard
library and h5py only, so that it runs without this package)."""
