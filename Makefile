# Thin wrapper around meson so that a fresh Debian machine needs two commands:
#   make report   install what is missing, build, reproduce the paper, write reports/out/
#   make check    install what is missing, build, run the test suite
BUILD     ?= build
MESONFLAGS ?=
DEBS = meson ninja-build pkg-config gcc libgsl-dev libcmocka-dev libinih-dev \
       libcjson-dev gnuplot-nox
SUDO = $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps build check check-asan report report-full bench clean

all: build

# Installs only the Debian packages that are missing, and says which.
deps:
	@missing=""; for p in $(DEBS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
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

report: build
	$(BUILD)/delam report

report-full: build
	$(BUILD)/delam verify --full --out out/verify-full
	$(BUILD)/delam report --from out/verify-full

bench: build
	$(BUILD)/delam bench

clean:
	rm -rf $(BUILD)
