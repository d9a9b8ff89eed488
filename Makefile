# The two commands: `make run` and `make test`. Both install what is missing
# (Debian packages, scripts/install-deps.sh), then build.
JOBS ?= $(shell nproc)
MAKEFLAGS += --no-print-directory

.PHONY: all deps build app run test clean

all: build

deps:
	@scripts/install-deps.sh

# Everything: the program, its tests and benchmarks.
build: deps
	@cmake --preset default >/dev/null
	@cmake --build build -j $(JOBS)

# The program alone (and the core compiled for its web pages): what `make run` needs.
app: deps
	@cmake --preset default >/dev/null
	@cmake --build build -j $(JOBS) --target viewpipe

run: app
	@scripts/run.sh

test: build
	@scripts/install-deps.sh --test
	@scripts/test.sh

clean:
	rm -rf build build-dev build-asan build-fuzz
