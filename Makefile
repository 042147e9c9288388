# The README's two commands: `make run` and `make test`. CMake does the building, into build/.
BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
WORLD ?= world/rotate.w

.PHONY: all deps run test test-sanitize clean

all: $(BUILD_DIR)/Makefile
	cmake --build $(BUILD_DIR) -j $(JOBS)
	cp -f $(BUILD_DIR)/jello ./jello

$(BUILD_DIR)/Makefile: CMakeLists.txt tests/CMakeLists.txt
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

# Installs the Debian packages the project needs, when some are missing and we can.
deps:
	@scripts/install-deps

run: deps all
	./jello --headless $(WORLD)

test: deps all
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The whole suite once more under AddressSanitizer and UndefinedBehaviorSanitizer.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DJELLO_SANITIZE=ON
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) jello
