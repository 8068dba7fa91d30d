# Thin wrapper around meson so that a fresh Debian machine needs two commands:
#   make report   install what is missing, build, reproduce the paper, write reports/out/
#   make check    install what is missing, build, run the test suite
#   make check-asan   the kernel, analytic, verify unit and robustness tests under AddressSanitizer + UBSan
#   make fuzz     build the libFuzzer target for the scene parser and run it FUZZ_TIME seconds
#                 (installs clang and its libFuzzer runtime when missing)
#   make fuzz-check   the same for delam check's readers (load.csv, summary.json)
#   make fe-data  rerun the FreeFEM reference scripts of data/fe/ (installs freefem++ when missing)
BUILD     ?= build
MESONFLAGS ?=
# A/B: either package will do, A is installed when neither is.  VTK's Python module
# (test vtk-readback) comes with python3-vtk9 or with ParaView's python3-paraview, which
# Debian 12 lets not be installed together: installing one removes the other.
DEBS = meson ninja-build pkg-config gcc libgsl-dev libcmocka-dev libinih-dev \
       libcjson-dev libsuitesparse-dev gnuplot-nox parallel python3-vtk9/python3-paraview
SUDO = $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps build check check-asan fuzz fuzz-check fuzz-deps report report-full bench docs-keys clean fe-data

all: build

# Installs only the Debian packages that are missing, and says which.
deps:
	@missing=""; for p in $(DEBS); do \
	  ok=""; for a in $$(echo $$p | tr / ' '); do \
	    dpkg-query -W -f='$${Status}' $$a 2>/dev/null | grep -q 'install ok installed' && ok=1; \
	  done; \
	  [ -n "$$ok" ] || missing="$$missing $${p%%/*}"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing from Debian:$$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "make deps: all Debian packages present"; fi

$(BUILD)/build.ninja:
	meson setup $(BUILD) $(MESONFLAGS)

build: deps $(BUILD)/build.ninja
	ninja -C $(BUILD)

check: build
	meson test -C $(BUILD) --print-errorlogs

# Sanitizers: a debug build in build-asan at -O1 (AddressSanitizer's advice for a usable
# speed: the kernel tests' longest, mpm_iface, took 333-371 s of its 600 at -O0 and 258 s
# at -O1 on this machine); not the long verify suite.  An existing build-asan keeps the
# options it was set up with: remove it to take these.
BUILD_ASAN ?= build-asan
$(BUILD_ASAN)/build.ninja:
	meson setup $(BUILD_ASAN) -Dbuildtype=debug -Doptimization=1 -Db_sanitize=address,undefined -Db_lundef=false $(MESONFLAGS)

check-asan: deps $(BUILD_ASAN)/build.ninja
	ninja -C $(BUILD_ASAN)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  meson test -C $(BUILD_ASAN) --print-errorlogs --suite kernel --suite analytic --suite verify-unit --suite robustness

# libFuzzer (clang): the scene parser and validator with the kernel sources they link
# against.  Seeds: data/scenes, data/bad and fuzz/corpus (inputs that reach code those
# do not; to refresh it, merge build-fuzz/corpus into a copy of the data/ scenes with
# -merge=1 -use_counters=0 and keep the files added).  New inputs go to
# build-fuzz/corpus, crashes to build-fuzz/crash-*: turn those into data/bad/ files.
FUZZ_CC ?= clang
FUZZ_TIME ?= 60
FUZZ_DEBS = clang libclang-rt-dev
FUZZ_SRC = fuzz/fuzz_scene.c verify/scene.c verify/scene_keys.c verify/scene_method.c verify/scene_check.c \
  verify/scene_ini.c verify/datadir.c verify/build_info.c $(wildcard kernel/*.c)
# build_info.c reads two headers that meson generates into $(BUILD)/verify.
FUZZ_GEN = $(BUILD)/verify/delam_config.h $(BUILD)/verify/delam_vcs.h
$(FUZZ_GEN): $(BUILD)/build.ninja
	ninja -C $(BUILD) verify/delam_vcs.h

build-fuzz/fuzz_scene: $(FUZZ_SRC) verify/scene.h kernel/mpm.h $(FUZZ_GEN)
	@mkdir -p build-fuzz/corpus
	$(FUZZ_CC) -g -O1 -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wno-unknown-pragmas -Wno-psabi \
	  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -Ikernel -Ianalytic -Iverify \
	  -I$(BUILD)/verify $(FUZZ_SRC) -linih -lgsl -lklu -lumfpack -lm -o $@

# clang and its libFuzzer runtime, installed only when missing (as deps does).
fuzz-deps:
	@$(MAKE) --no-print-directory deps DEBS="$(FUZZ_DEBS)"

fuzz: deps fuzz-deps build-fuzz/fuzz_scene
	build-fuzz/fuzz_scene -max_total_time=$(FUZZ_TIME) -dict=fuzz/scene.dict -max_len=8192 \
	  -artifact_prefix=build-fuzz/ -print_final_stats=1 build-fuzz/corpus fuzz/corpus data/scenes data/bad

# delam check's readers: foreign.c (CSV) and check_folder.c (summary.json) built with
# the fuzzer, the rest they call from the meson build's libraries.  Seeds: fuzz/corpus-check.
FUZZ_CHECK_SRC = fuzz/fuzz_check.c verify/foreign.c verify/check_folder.c verify/io.c verify/datadir.c
FUZZ_CHECK_LIBS = $(BUILD)/verify/libver.a $(BUILD)/verify/libverscene.a $(BUILD)/kernel/libmpm.a $(BUILD)/analytic/libana.a
build-fuzz/fuzz_check: $(FUZZ_CHECK_SRC) verify/foreign.h verify/check_folder.h build
	@mkdir -p build-fuzz/corpus-check
	$(FUZZ_CC) -g -O1 -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wno-unknown-pragmas -Wno-psabi \
	  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -Ikernel -Ianalytic -Iverify \
	  -I$(BUILD)/verify $(FUZZ_CHECK_SRC) $(FUZZ_CHECK_LIBS) -fopenmp -lcjson -linih -lgsl -lgslcblas -lklu -lumfpack -lm -o $@

fuzz-check: deps fuzz-deps build-fuzz/fuzz_check
	build-fuzz/fuzz_check -max_total_time=$(FUZZ_TIME) -max_len=8192 -artifact_prefix=build-fuzz/ \
	  -print_final_stats=1 build-fuzz/corpus-check fuzz/corpus-check

report: build
	$(BUILD)/delam report

report-full: build
	$(BUILD)/delam verify --full --out out/verify-full
	$(BUILD)/delam report --from out/verify-full

bench: build
	$(BUILD)/delam bench

# docs/scene-keys.md: the table between its markers, from the parser's own key table
# (make check fails when they differ).
docs-keys: build
	$(BUILD)/delam run --keys > $(BUILD)/keys.md
	awk -v t=$(BUILD)/keys.md '/<!-- keys: end -->/{while ((getline l < t) > 0) print l; skip=0} \
	  !skip{print} /<!-- keys: begin -->/{skip=1}' docs/scene-keys.md > docs/scene-keys.md.tmp
	mv docs/scene-keys.md.tmp docs/scene-keys.md

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) build-fuzz

# data/fe/: the FreeFEM reference numbers.  Installs freefem++ when missing and reruns the
# scripts (several minutes); make check reads the stored .dat files and does not need it.
FE_DEBS = freefem++
fe-data:
	@$(MAKE) --no-print-directory deps DEBS="$(FE_DEBS)"
	data/fe/run.sh
