# The README's two commands: `make run` and `make test`. CMake does the building, into build/.
BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
WORLD ?= world/rotate.w
CLANG_FORMAT ?= clang-format-14

.PHONY: all deps run test test-sanitize format-check fuzz vec-report animation clean

all: $(BUILD_DIR)/Makefile
	cmake --build $(BUILD_DIR) -j $(JOBS)
	cp -f $(BUILD_DIR)/jello $(BUILD_DIR)/createWorld $(BUILD_DIR)/grade .

$(BUILD_DIR)/Makefile: CMakeLists.txt tests/CMakeLists.txt
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

# Installs the Debian packages the project needs, when some are missing and we can.
deps:
	@scripts/install-deps

# The window where a display exists; otherwise frames, in a new folder that jello names.
run: deps all
	./jello $(WORLD)

# 300 frames of world/rotate.w in animation/, and an animated GIF of them where ffmpeg or
# ImageMagick is installed.
animation: all
	./jello --headless --overwrite --frames animation $(WORLD)
	@if command -v ffmpeg >/dev/null; then \
	  ffmpeg -y -loglevel error -framerate 30 -i animation/%04d.jpg \
	    -vf "fps=15,scale=320:-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse" animation/jello.gif && \
	  echo "animation/jello.gif"; \
	elif convert -version 2>/dev/null | grep -q ImageMagick; then \
	  convert -delay 7 -loop 0 $$(ls animation/*.jpg | awk 'NR % 2 == 1') -resize 320x240 -layers Optimize animation/jello.gif && \
	  echo "animation/jello.gif"; \
	else echo "no ffmpeg or ImageMagick: frames only"; fi

test: deps all
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The whole suite once more, built by clang with AddressSanitizer and UndefinedBehaviorSanitizer,
# float-cast-overflow included (a NaN or too large a double converted to an integer: GCC's UBSan
# does not check it), invariants checked (JELLO_ASSERT) and warnings as errors (JELLO_WERROR).
# Every UBSan report, in the tests or in the programs they start, is written to
# $(SANITIZE_DIR)/ubsan-reports/ and fails the target.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
		-DJELLO_SANITIZE=ON -DJELLO_WERROR=ON
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	rm -rf $(SANITIZE_DIR)/ubsan-reports && mkdir -p $(SANITIZE_DIR)/ubsan-reports
	@status=0; cd $(SANITIZE_DIR) && \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:log_path=$$PWD/ubsan-reports/report \
		ctest --output-on-failure -j $(JOBS) || status=1; \
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
	@for f in forces/springs.cpp forces/walls.cpp forces/plane.cpp forces/field.cpp forces/term.cpp; do \
		$(CXX) -std=c++17 -O3 -DNDEBUG -march=native -ffp-contract=off -fno-math-errno -fno-trapping-math -I. \
		-c $$f -o /dev/null -fopt-info-vec-optimized 2>&1 | grep "^$$f.*loop vectorized" | sort -t: -k2 -n -u; done

# The libFuzzer targets (clang, ASan, UBSan), each run for FUZZ_SECONDS; fails on any finding.
fuzz: deps
	cmake -S . -B $(FUZZ_DIR) -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DJELLO_FUZZ=ON \
		-DJELLO_TESTS=OFF -DJELLO_GRAPHICS=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target fuzz_world_reader fuzz_field_expression fuzz_command_line
	scripts/run-fuzzers $(FUZZ_DIR) $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(UBSAN_DIR) $(FUZZ_DIR) jello createWorld grade
