# PECPLAS/PECJOIN: on a fresh Debian 12 machine `make run` and `make test` are all it takes;
# both first run tools/install_deps.sh (installs as root, else says what to install).
# See doc/build.md. `make help` lists the targets.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := help

PYTHON ?= python3
# `pip install fpm` puts fpm in the interpreter's scripts dir (or the user base); pyenv's
# shims only know it after a rehash. Look in both, so a just-installed fpm is found.
PY_SCRIPTS := $(shell $(PYTHON) -c 'import sysconfig; print(sysconfig.get_path("scripts"))' 2>/dev/null)
PY_USERBASE := $(shell $(PYTHON) -m site --user-base 2>/dev/null)
export PATH := $(if $(PY_SCRIPTS),$(PY_SCRIPTS):)$(PATH)$(if $(PY_USERBASE),:$(PY_USERBASE)/bin)
export PYTHON
# The Python tools are one package, tools/pecplas_py (doc/tools.md): every script runs as
# `$(PYTHON) -m pecplas_py.<role>.<script>` with tools/ on PYTHONPATH.
export PYTHONPATH := $(CURDIR)/tools$(if $(PYTHONPATH),:$(PYTHONPATH))

FPM ?= fpm
DECK ?= input/default.inp
OUT ?= output/$(basename $(notdir $(DECK))).h5
CMAKE_DIR ?= build/cmake
JOBS ?= 2
PREFIX ?= $(HOME)/.local
export FPM CMAKE_DIR JOBS

.PHONY: help deps build run test bench clean s1 s2 s3 s4 s5 s6 install test-slurm build-mpi test-mpi docs phases

help:
	@echo "PECPLAS/PECJOIN make targets (details: doc/build.md)"
	@echo "  make run      install what is missing, build (release) and run $(DECK) -> $(OUT)"
	@echo "                DECK=path/to/deck.inp [OUT=path/to/results.h5] to choose"
	@echo "  make test     fpm test (debug) + CMake build and ctest (release) + pytest test/python"
	@echo "  make build    fpm build --profile release"
	@echo "  make install  build (release) and install pecplas, pecplas-path, pecplas-identify,"
	@echo "                pecplas-sensitivity, pecplas-sweep, pecplas-plot and pecplas-slope"
	@echo "                into PREFIX/bin"
	@echo "                (PREFIX=$(PREFIX))"
	@echo "  make test-slurm  start a one-node Slurm here and run the S2 mesh series as a job"
	@echo "                array through pecplas-sweep (doc/sweep.md; needs root or Slurm)"
	@echo "  make build-mpi  the MPI build with the MUMPS solver in $(MPI_DIR) (installs OpenMPI"
	@echo "                and MUMPS as root; doc/mpi.md): mpirun -np N $(MPI_DIR)/pecplas DECK"
	@echo "  make test-mpi MUMPS on 1 and 2 ranks against the serial solvers (6 decks, 1e-8)"
	@echo "                and the MUMPS unit tests under mpirun -np 1 and 2"
	@echo "  make deps     check (as root: install) compilers, libraries and Python packages"
	@echo "  make s1       scene S1 (shear box): all decks of input/s1, PNGs in output/s1"
	@echo "  make s2, s3   scenes S2 (pile, interface models) and S3 (dilatancy), PNGs in output/"
	@echo "  make s4       scene S4 (MODJOIN on homogeneous paths): input/s4 with pecplas-path,"
	@echo "                identification and sensitivity tables, PNGs in output/s4"
	@echo "  make s5       scene S5 (FE shear box, MODJOIN cyclic) and its point-driver check,"
	@echo "                PNGs in output/s5"
	@echo "  make s6       scene S6 (pile pull-out, MODJOIN and Mohr-Coulomb, table IV.1 variants),"
	@echo "                PNGs in output/s6"
	@echo "  make phases   the staged-construction examples of input/examples (cantilever wall,"
	@echo "                pile wished in place, embankment in lifts), their numbers in"
	@echo "                doc/validation.md and PNGs in output/phases and doc/img"
	@echo "  make bench    benchmark suite (tools/bench.sh, ~38 min; ~48 with MPI): overhead vs bare CHOLMOD,"
	@echo "                stability maps, scaling, work-precision + advice, CalculiX and"
	@echo "                OpenSees side by side; CSV/PNG and README.md in doc/bench/ (BENCH=quick: ~4 min)"
	@echo "  make docs     rewrite every generated block of the docs from fresh runs: scenes S1-S6"
	@echo "                (as make s1 ... s6) and the numbers of the test suites quoted in"
	@echo "                doc/validation.md and doc/theory.md (pecplas_py.docs.validation_report,"
	@echo "                hertz_report, theory_report: minutes, stored in test/reference)"
	@echo "  make clean    remove build/ (fpm and CMake builds); results in output/ stay"
	@echo "One suite:  fpm test -- SUITE [TEST]   or   ctest --test-dir $(CMAKE_DIR) -R SUITE"

deps:
	@bash tools/install_deps.sh

build: deps
	@bash tools/fpm_fresh.sh
	@bash tools/build_info.sh
	$(FPM) build --profile release

run: build
	@test -f "$(DECK)" || { echo "make run: no deck $(DECK) (choose one with DECK=path/to/deck.inp)" >&2; exit 1; }
	@mkdir -p "$(dir $(OUT))"
	$(FPM) run --profile release --target pecplas -- "$(DECK)" -o "$(OUT)"
	@test -f "$(OUT)" || { echo "make run: pecplas wrote no $(OUT)" >&2; exit 1; }
	@$(PYTHON) -m pecplas_py.plots.plot_results "$(OUT)" -o "$(basename $(OUT)).png" || echo "make run: no picture (matplotlib missing?)"
	@echo "make run: results of $(DECK) written to $(OUT) (+ $(basename $(OUT)).xmf for ParaView, $(basename $(OUT)).png)"

test: deps
	@bash tools/test_all.sh

install: deps
	@bash tools/fpm_fresh.sh
	@bash tools/install.sh "$(PREFIX)"

test-slurm: build
	@bash tools/slurm_test.sh

s1: build
	@mkdir -p output/s1
	@for d in input/s1/*.inp; do \
	  n=$$(basename $$d .inp); \
	  $(FPM) run --profile release --target pecplas -- $$d -o output/s1/$$n.h5 --quiet \
	    2>/dev/null && rc=0 || rc=$$?; \
	  echo "make s1: $$n exit $$rc (0 completed, 3 stopped: limit load or divergence)"; \
	done
	@$(PYTHON) -m pecplas_py.scenes.plot_s1 output/s1
	@$(PYTHON) -m pecplas_py.scenes.s1_report output/s1

s2 s3: build
	@mkdir -p output/$@
	@for d in input/$@/*.inp; do \
	  n=$$(basename $$d .inp); \
	  $(FPM) run --profile release --target pecplas -- $$d -o output/$@/$$n.h5 --quiet \
	    2>/dev/null && rc=0 || rc=$$?; \
	  echo "make $@: $$n exit $$rc"; \
	done
	@$(PYTHON) -m pecplas_py.scenes.plot_s2 output
	@if [ -d output/s2 ] && [ -d output/s3 ]; then \
	  $(PYTHON) -m pecplas_py.scenes.s2_report output; \
	  else echo "make $@: run make s2 s3 to write the S2/S3 numbers of the docs"; fi
# S4: every path deck, then the identification of the CNL curves (thesis III.17-III.20) and
# the sensitivity table (III.4), then the figures; pecplas_py.scenes.s4_report then writes
# the S4 numbers of doc/validation.md. The tables are also kept as .txt files.
S4_RUN = $(FPM) run --profile release --target
s4: build
	@mkdir -p output/s4
	@for d in input/s4/*.inp; do \
	  n=$$(basename $$d .inp); \
	  $(S4_RUN) pecplas-path -- $$d -o output/s4/$$n --quiet 2>/dev/null && rc=0 || rc=$$?; \
	  echo "make s4: $$n exit $$rc (0 completed, 3 stopped early)"; \
	done
	@for t in iii1 iii2 iii5; do \
	  v=improved; [[ $$t == iii1 ]] && v=initial; \
	  $(S4_RUN) pecplas-identify -- --version $$v output/s4/s4_$${t}_cnl_{31,56,122}.csv \
	    -o output/s4/identification_$$t.csv 2>&1 | tee output/s4/identification_$$t.txt \
	    || echo "make s4: identification of $$t failed"; \
	done
	@$(S4_RUN) pecplas-sensitivity -- -o output/s4/sensitivity.csv 2>&1 \
	  | tee output/s4/sensitivity.txt
	@$(PYTHON) -m pecplas_py.scenes.plot_s4 output/s4
	@$(PYTHON) -m pecplas_py.scenes.s4_report output/s4

# S5: the FE shear box, then the figures (scenes/plot_s5.py runs pecplas-path on the mid-interface path).
s5: build
	@mkdir -p output/s5
	@$(FPM) run --profile release --target pecplas -- input/s5/s5_shear_box.inp \
	  -o output/s5/s5_shear_box.h5 --quiet && echo "make s5: s5_shear_box completed"
	@$(PYTHON) -m pecplas_py.scenes.plot_s5 output/s5
	@$(PYTHON) -m pecplas_py.scenes.s5_report output/s5

s6: build
	@mkdir -p output/s6
	@for d in input/s6/*.inp; do \
	  n=$$(basename $$d .inp); \
	  $(FPM) run --profile release --target pecplas -- $$d -o output/s6/$$n.h5 --quiet \
	    2>/dev/null && rc=0 || rc=$$?; \
	  echo "make s6: $$n exit $$rc (0 completed, 3 stopped: limit load or divergence)"; \
	done
	@$(PYTHON) -m pecplas_py.scenes.plot_s6 output/s6
	@$(PYTHON) -m pecplas_py.scenes.s6_report output/s6

# The optional MPI build (doc/mpi.md): the CMake tree of `make test` configured with
# -DPECPLAS_MPI=ON, which adds MPI flavours of pecplas and of the test driver in $(MPI_DIR),
# linked with the serial programs' own Fortran objects (only the C shims and the two main
# programs are compiled again); the serial programs stay as they are.
MPI_DIR = $(CMAKE_DIR)/mpi
MPI_DECKS ?= input/default.inp test/data/plasticity/footing_t6.inp input/s2/s2_katona.inp \
  test/data/katona/float_goodman6_axi.inp input/examples/excavation_cantilever.inp \
  test/data/plates/footing_beam.inp
build-mpi:
	@PECPLAS_MPI=1 bash tools/install_deps.sh
	cmake -S . -B $(CMAKE_DIR) -DPECPLAS_MPI=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(CMAKE_DIR) -j$(JOBS) --target pecplas_mpi

test-mpi: build-mpi
	cmake --build $(CMAKE_DIR) -j$(JOBS) --target pecplas_tests_mpi
	$(PYTHON) -m pecplas_py.checks.mpi_check $(MPI_DIR)/pecplas $(MPI_DECKS) --np 1 2 \
	  --singular test/data/cli/roller_only.inp --restart test/data/plasticity/footing_t6.inp 13 \
	  --restart-exact input/default.inp 15 --restart-exact input/examples/excavation_cantilever.inp 7 \
	  --signal test/data/plasticity/footing_t6.inp --write-failure test/data/plasticity/footing_t6.inp \
	  --unit $(MPI_DIR)/pecplas_tests linalg_mumps

bench: deps
	@bash tools/bench.sh

# Every generated block of the docs (text between
# `<!-- BEGIN generated by tools/pecplas_py/SCRIPT: NAME -->` and `<!-- END generated: NAME -->`):
# the scenes write theirs, pecplas_py.docs.validation_report runs the test suites whose numbers
# the docs quote, pecplas_py.scenes.s1_stability renders its stored runs.
phases: build
	@$(PYTHON) -m pecplas_py.scenes.phases_report output/phases --figures

docs: s1 s2 s3 s4 s5 s6 phases
	$(PYTHON) -m pecplas_py.docs.validation_report output/validation --run
	$(PYTHON) -m pecplas_py.docs.hertz_report output/hertz --run
	$(PYTHON) -m pecplas_py.docs.theory_report output/theory --run
	$(PYTHON) -m pecplas_py.scenes.s1_stability --doc

clean:
	rm -rf build .pytest_cache
	find . -name __pycache__ -type d -prune -exec rm -rf {} +
