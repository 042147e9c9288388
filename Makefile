# The README's two commands: `make run` and `make test`. CMake does the building, into build/:
# `make` and `make run` build the three programs only; `make test` builds the rest (the tests,
# the benchmarks) too.
BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_SECONDS ?= 60
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
WORLD ?= world/rotate.w
SECONDS ?= 3
FPS ?= 30
CLANG_FORMAT ?= clang-format-14

.PHONY: programs all deps deps-run run test test-quick test-sanitize format-check fuzz vec-report bench animation docs clean

# The three programs, left at the top level as the course's Makefile left ./jello.
programs: $(BUILD_DIR)/Makefile
	cmake --build $(BUILD_DIR) -j $(JOBS) --target jello createWorld grade
	cp -f $(BUILD_DIR)/jello $(BUILD_DIR)/createWorld $(BUILD_DIR)/grade .

# Everything: the programs, the tests, the benchmarks. CMake looks again first, so that test
# packages installed since the last build are found.
all:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD_DIR) -j $(JOBS)
	cp -f $(BUILD_DIR)/jello $(BUILD_DIR)/createWorld $(BUILD_DIR)/grade .

# A fresh clone's first `make` installs what building needs first (as `make run` does), or
# says in one line which packages are missing.
$(BUILD_DIR)/Makefile: CMakeLists.txt tests/CMakeLists.txt
	@scripts/install-deps --run
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

# Installs the Debian packages the project needs, when some are missing and we can: all of them,
# or (deps-run) only what building and running the programs needs.
deps:
	@scripts/install-deps
deps-run:
	@scripts/install-deps --run

# The window where a display exists; otherwise frames, in a new folder that jello names.
run: deps-run programs
	./jello $(WORLD)

# SECONDS of WORLD as frames in animation/ (FPS a second), then animation/jello.gif and
# animation/jello.mp4 playing in real time, where ffmpeg is installed (make deps installs it).
animation: programs
	./jello --headless --overwrite --time $(SECONDS) --fps $(FPS) --frames animation $(WORLD)
	@if command -v ffmpeg >/dev/null; then \
	  scripts/frames-to-video animation $(FPS) animation/jello.gif animation/jello.mp4; \
	else echo "no ffmpeg (make deps installs it): frames only, in animation/"; fi

# Every picture in docs/ made again from the current code: the README's frame and GIF, the
# --report and --check --map plots, the window with its overlay (where Xvfb is installed).
docs: deps programs
	scripts/make-docs

test: deps all
	cd $(BUILD_DIR) && ctest --output-on-failure --no-tests=error -j $(JOBS)

# A developer's loop: the suite without the tests labelled `long` (tests/labels.cmake: 5 s or
# more each, the grader's class runs and the longest runs of physics), which `make test` runs.
test-quick: deps all
	cd $(BUILD_DIR) && ctest --output-on-failure --no-tests=error -j $(JOBS) -LE long

# The sanitizers' build: clang, AddressSanitizer, UndefinedBehaviorSanitizer (float-cast-overflow
# too), libFuzzer's coverage, invariants checked, warnings as errors, no benchmarks. The suite
# under the sanitizers and the fuzzers share it: one instrumented build, not two.
SANITIZE_CONFIGURE = cmake -S . -B $(SANITIZE_DIR) -DCMAKE_CXX_COMPILER=clang++ \
	-DCMAKE_BUILD_TYPE=RelWithDebInfo -DJELLO_SANITIZE=ON -DJELLO_FUZZ=ON -DJELLO_WERROR=ON \
	-DJELLO_BENCHMARKS=OFF

# The whole suite once more, built by clang with AddressSanitizer and UndefinedBehaviorSanitizer,
# float-cast-overflow included (a NaN or too large a double converted to an integer: GCC's UBSan
# does not check it), invariants checked (JELLO_ASSERT) and warnings as errors (JELLO_WERROR).
# Every UBSan report, in the tests or in the programs they start, is written to
# $(SANITIZE_DIR)/ubsan-reports/ and fails the target.
# The tests labelled `sanitizers` (tests/labels.cmake: 20 s or more under the sanitizers, whose
# code shorter tests take through them too) are left out: the grader's class runs, whose own
# students' code no sanitizer sees, and the long runs of physics, 10 to 60 times slower there.
test-sanitize: deps
	$(SANITIZE_CONFIGURE)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	rm -rf $(SANITIZE_DIR)/ubsan-reports && mkdir -p $(SANITIZE_DIR)/ubsan-reports
	@status=0; cd $(SANITIZE_DIR) && \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:log_path=$$PWD/ubsan-reports/report \
		ctest --output-on-failure -j $(JOBS) -LE sanitizers || status=1; \
	if [ -n "$$(ls ubsan-reports)" ]; then \
	  echo "test-sanitize: UndefinedBehaviorSanitizer reports:"; cat ubsan-reports/*; status=1; fi; \
	exit $$status

# Fails, naming each file and line, where a .cpp or .h file of the project differs from what the
# project's .clang-format (clang-format 14) makes of it; changes nothing. tests/data/ is data:
# the grader's fixtures are students' code as written, mistakes and all.
format-check:
	$(CLANG_FORMAT) --dry-run -Werror $$(git ls-files '*.cpp' '*.h' ':!:tests/data/*')

# The compiler's vectorisation report on the force terms: which loops became vector loops.
vec-report:
	@for f in model/springs.cpp model/walls.cpp model/plane.cpp model/field.cpp model/term.cpp physics.cpp model/model.cpp; do \
		$(CXX) -std=c++17 -O3 -DNDEBUG -march=native -ffp-contract=off -fno-math-errno -fno-trapping-math -I. \
		-c $$f -o /dev/null -fopt-info-vec-optimized 2>&1 | grep "^$$f.*loop vectorized" | sort -t: -k2 -n -u; done

# The force kernel and the RK4 step of the five course worlds (scripts/bench-against), then of
# lattices of 8^3 to 48^3 points and a voxelised model on 1, 2 and all the cores
# (scripts/bench-bodies), this tree against TAG (default: the last commit before issue 30's grid
# kernel and thread pool, built once into build-before/): markdown tables of medians of
# interleaved runs. TAG and ROUNDS reach the scripts through their environment, never through a
# shell command line.
TAG ?= 65a1e66a6bee4627eed654cc59d94c4ae3d7e24a
ROUNDS ?= 3
bench: export BENCH_TAG = $(TAG)
bench: export BENCH_ROUNDS = $(ROUNDS)
bench: programs
	scripts/bench-against
	scripts/bench-bodies

# The libFuzzer targets, in the sanitizers' build, each run for FUZZ_SECONDS; fails on any
# finding. After `make test-sanitize` there is nothing left to build.
fuzz: deps
	$(SANITIZE_CONFIGURE)
	cmake --build $(SANITIZE_DIR) -j $(JOBS) --target fuzz_world_reader fuzz_field_expression fuzz_command_line fuzz_scene_reader fuzz_obj_voxels
	scripts/run-fuzzers $(SANITIZE_DIR) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) build-fuzz build-before jello createWorld grade
