# imasim: the two commands (`make demo`, `make test`) and friends.
# Each target installs missing Debian packages first (scripts/install-deps.sh).
JOBS ?= $(shell nproc)
BUILD ?= build
ASAN_BUILD ?= build-asan
TSAN_BUILD ?= build-tsan
CMAKE_FLAGS ?=

.PHONY: deps configure build build-app python demo test harvest-check harvest-ci unit-asan fuzz-build fuzz-short fuzz tsan soak format-check layer-check format bench clean

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DIMASIM_WERROR=ON $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# Only the program `make demo` runs: a newcomer's first command does not compile the tests.
build-app: configure
	cmake --build $(BUILD) -j $(JOBS) --target imasim

# The Python module (docs/python.md): built, and put on Debian's /usr/bin/python3's path by a
# .pth file naming $(BUILD)/python, so `import imasim` works from anywhere (as root, like deps).
PYTHON_SITE = /usr/local/lib/python3.$(shell /usr/bin/python3 -c 'import sys; print(sys.version_info.minor)')/dist-packages
python: configure
	cmake --build $(BUILD) -j $(JOBS) --target imasim_python_module
	mkdir -p $(PYTHON_SITE)
	echo "$(abspath $(BUILD))/python" > $(PYTHON_SITE)/imasim.pth
	/usr/bin/python3 -c "import imasim; print('python: import imasim from', imasim.__file__)"

# The main job: the scripted operator harvests the IMA with the beating and the static heart (3
# trials each, in parallel processes), then a summary and out/report.html (docs/scoring.md).
demo: build-app
	$(BUILD)/apps/imasim/imasim demo --out out --jobs $(JOBS) --db $(BUILD)/trainees.sqlite

format-check: deps
	bash scripts/check-format.sh

layer-check:
	bash scripts/check-layers.sh

# Release build with -Werror and every ctest, then the unit tests again under ASan+UBSan
# with the expensive invariant checks (IMASIM_VALIDATION) switched on. The longest full-length
# scene runs (seconds of a converged solve, 1-2 minutes each under ASan) run in Release only;
# shorter runs of the same code stay in the ASan set: the heart against the proxies
# (InstrumentsStopAtTheHeart, AnInstrumentDoesNotPassThroughTheHeart), the beating thorax
# (DeterministicAcrossThreadCountsAndHasItsPorts), the implicit fascia's holds and contacts on
# proxies (AProxysHoldLifts..., AProxysContactPushes..., MembraneFriction.*), its planes
# (MembraneContact's single vertices, ImplicitFasciaScene's beating scene), the proxy's contact
# rows (ToolProxy's single steps), the strands' tears (StrandTear's single strands), the grasp
# (Grasp's holds on the jaws), a patient's heart (PatientHeart's refusals).
ASAN_SKIP_TESTS = TheExampleScriptOpensGraspsCutsAndCoagulates ACutOpensAsTheXpbdFasciasDoes \
	StiffnessOfTheCouplingSetsTheIndentation SameHashAcrossRunsAndThreadCounts \
	AScriptedSessionIsBitForBitRepeatableWhateverTheThreads \
	NoTissueParticleInsideTheHeartAfterSecondsOfBeating VariedPatientsSimulateWithNoTissueInTheHeart \
	LiftingTheFasciaLiftsTheFatUnderItLessWithDistance SettlesUnderGravityWithStrandEndsOnTheirSurfaces \
	AFreedPieceOfFasciaRestsOnTheFloorInsteadOfFallingAcrossTheCavity \
	AnInstrumentWhoseDeviceIsLostHoldsStillWithNoEnergy \
	RetractingTheFatMovesTheVesselAndLetGoItComesToRest \
	TheHeartPushesTheProxyBackWithTheCouplingsSpring AnInstrumentTheHeartBeatsIntoRidesOnItsSurface \
	StaticHeartTransmitsNoMotion HeartMotionReachesTheImaAndFallsWithDistance \
	AHoldOnAProxyStoppedByASurfaceStaysOnTheProxy AProxysContactDragsTheFasciaAlongByItsFriction \
	ASheetOnAHeavingPlaneConvergesInAFewIterationsAStep \
	PressingFiveMillimetresRestsOnTheSurfaceAndTheCouplingCarriesTheTissuesPush \
	TheFasciaLaidOnItsFatSinksItsWeightOverItsColumns \
	StrandsOnTissueCarriedAwayTearAsTheyPassTheLimit ForcepsLiftTheFasciaAndTheFatUnderItThenRelease \
	AnOpenLvWithARepeatedApexLoadsAndIsPlacedUnderTheIma
empty :=
space := $(empty) $(empty)
ASAN_SKIP = $(subst $(space),|,$(strip $(ASAN_SKIP_TESTS)))
# Each stage says when it starts, so a slow CI run shows where its time went.
test: format-check layer-check build python
	@date -u +'[%T] make test: the Release tests'
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE harvest
	@date -u +'[%T] make test: the sanitizer build and its unit tests'
	$(MAKE) unit-asan
	@date -u +'[%T] make test: the fuzzers'
	$(MAKE) fuzz-short
	@date -u +'[%T] make test: done'

# One sanitizer build serves the unit tests and the fuzz targets: clang (libFuzzer needs it),
# ASan+UBSan, IMASIM_VALIDATION's invariant checks, and coverage on every library for the
# fuzzers. -O1 with line tables only: the reports keep their file:line, and the build (the larger
# part of CI's time) needs about a third less CPU than -O2 -g. One build instead of a GCC one for
# the tests and a clang one for the fuzzers saves CI about three minutes of building; the
# coverage makes the unit tests about a minute slower.
SANITIZE_CONFIGURE = cmake -S . -B $(ASAN_BUILD) -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DIMASIM_WERROR=ON -DIMASIM_SANITIZE=ON -DIMASIM_VALIDATION=ON -DIMASIM_FUZZ=ON \
	  -DIMASIM_BUILD_BENCH=OFF $(CMAKE_FLAGS)
unit-asan: deps
	$(SANITIZE_CONFIGURE)
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target imasim_unit_tests imasim_ui_tests imasim_fuzzers
	cd $(ASAN_BUILD) && LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp \
	  ctest --output-on-failure -j $(JOBS) -L unit -E '$(ASAN_SKIP)'

# libFuzzer targets (fuzz/): the scene file, each mesh format, the input script, the command
# line and OpenIGTLink messages, built in the sanitizer build above. `make test` runs each for a
# few seconds from the committed corpus (fuzz/corpus); `make fuzz` runs them for longer.
# Findings stay in $(ASAN_BUILD)/fuzz-artifacts; new coverage in $(ASAN_BUILD)/fuzz-found.
FUZZ_SHORT_SECONDS ?= 15
FUZZ_SECONDS ?= 600
fuzz-build: deps
	$(SANITIZE_CONFIGURE)
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target imasim_fuzzers
fuzz-short: fuzz-build
	bash scripts/run-fuzzers.sh $(ASAN_BUILD) $(FUZZ_SHORT_SECONDS)
fuzz: fuzz-build
	bash scripts/run-fuzzers.sh $(ASAN_BUILD) $(FUZZ_SECONDS)

# The parallel loops under ThreadSanitizer: the tests that step the cloth, the thoracic patch,
# search the heart, smooth the fat and cut on several threads (a full scene is too slow under
# TSan), and the worker team that runs them (scripts/tsan.supp suppresses nothing).
TSAN_TESTS = WorkerTeam.*:PinnedHash.Cloth*:ThoracicPatch.DeterministicAcrossThreadCounts:HeartParallel.*:SurfaceParallel.*:Xsph.TwoThreadsSmoothAsOne:FasciaCut.CuttingIsDeterministic:ToolContact.CloudAroundTheForcepsIsDeterministic:LatestValue.*:HapticLoop.*:IgtlLink.*:LiveConsole.*
tsan: deps
	cmake -S . -B $(TSAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIMASIM_WERROR=ON \
	  -DIMASIM_TSAN=ON -DIMASIM_BUILD_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(TSAN_BUILD) -j $(JOBS) --target imasim_unit_tests
	TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/scripts/tsan.supp \
	  $(TSAN_BUILD)/tests/imasim_unit_tests --gtest_filter='$(TSAN_TESTS)'

# 30 simulated minutes of the beating heart with repeated cutting, grasping, cautery and release
# (examples/soak_cycle.script played 157 times, 11.5 s a cycle), the events written as they
# happen: the run must end with status ok. About half an hour on one core.
SOAK_CYCLES ?= 157
soak: build
	$(BUILD)/apps/imasim/imasim run --headless --script examples/soak_cycle.script \
	  --repeat $(SOAK_CYCLES) --threads 1 --events $(BUILD)/soak_events.csv --progress --json \
	  > $(BUILD)/soak.json
	grep -q '"status":"ok"' $(BUILD)/soak.json

# The scripted operator's ten-patient study, dynamic and static (about 35 minutes of CPU, 18-25
# minutes on 2 cores): kept out of `make test`'s 15 minutes. CI runs its first four patients
# after `make test` (`make harvest-ci`, about 9 minutes; .ci/run) to stay within its hour.
harvest-check: build
	cd $(BUILD) && ctest --output-on-failure -L '^harvest$$'
harvest-ci: build
	cd $(BUILD) && ctest --output-on-failure -L '^harvest-ci$$'

format:
	bash scripts/check-format.sh --fix

bench: build
	mkdir -p $(BUILD)/bench
	$(BUILD)/bench/imasim_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
	  --benchmark_out=$(BUILD)/bench/imasim_bench.json --benchmark_out_format=json

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(TSAN_BUILD)
