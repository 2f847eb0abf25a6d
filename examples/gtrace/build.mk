# examples/gtrace/build.mk - gtrace's rules, included by the top Makefile: the tracer as a static library,
# BUILD/lib/libgtrace.a (the sources of its folders: everything but main.c), which the tool and its test programs
# link; Embree and assimp for them; the MPI module; and the benchmarks that run gtrace.
GTRACE_SRC := $(sort $(wildcard examples/gtrace/*/*.c))
GTRACE_LIB := $(BUILD)/lib/libgtrace.a
# assimp is not linked: geometry/mesh_assimp_lib.c loads it by its soname on the first PLY, STL or glTF file read
# in the process (a scene without one never maps it)
GTRACE_DEPLIBS := -lembree3
ASSIMP_SONAME := $(shell objdump -p "$$($(CC) -print-file-name=libassimp.so)" 2>/dev/null | sed -n 's/^ *SONAME *//p')
$(call objs_of,examples/gtrace/geometry/mesh_assimp_lib.o): \
    CPPFLAGS += $(if $(ASSIMP_SONAME),-DGTRACE_ASSIMP_SONAME='"$(ASSIMP_SONAME)"')
all: $(GTRACE_LIB)

$(GTRACE_LIB): $(GTRACE_SRC:%.c=$(BUILD)/obj/%.o)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# gtrace's files include each other as "folder/name.h" across its folders (and "name.h" within one)
$(call objs_of,examples/gtrace/%.o): CPPFLAGS += -Iexamples/gtrace
$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tests/test_gtrace*.c)): CPPFLAGS += -Iexamples/gtrace
# the test programs of the tracer link the library
GTRACE_TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(wildcard tests/test_gtrace*.c))
$(GTRACE_TEST_BIN): $(GTRACE_LIB)
$(GTRACE_TEST_BIN): TESTLIBS += $(GTRACE_LIB) $(GTRACE_DEPLIBS)
# the replay of the fuzz targets' inputs (tests/test_regress.c) runs the scene target's through gtrace too
$(BUILD)/obj/tests/test_regress.o: CPPFLAGS += -Iexamples/gtrace
$(BUILD)/tests/test_regress: $(GTRACE_LIB)
$(BUILD)/tests/test_regress: TESTLIBS += $(GTRACE_LIB) $(GTRACE_DEPLIBS)

ifeq ($(LTO),)
# the tool: main.c (the top Makefile's rule for examples/TOOL/*.c) and the library
EXTRA_LIBS_gtrace := $(GTRACE_LIB) $(GTRACE_DEPLIBS)
$(BUILD)/bin/gtrace: $(GTRACE_LIB)
else
# The tool, link-time optimised (LTO in the top Makefile): main.c and the library compiled for it into BUILD/obj-lto,
# the twin of libgtrace.a whole, and every object of libgeneric on the command line, as --whole-archive puts them on
# the others', so plug-ins find all of the library's symbols in the program. -Wmaybe-uninitialized stays a warning
# at this link: it looks across files there and is prone to false alarms (every object was compiled with it as an
# error).
GTRACE_LTO_LIB := $(BUILD)/obj-lto/libgtrace.a
LTO_OBJ := $(patsubst $(BUILD)/obj/%,$(BUILD)/obj-lto/%,$(LIB_OBJ)) $(BUILD)/obj-lto/examples/gtrace/main.o
$(GTRACE_LTO_LIB): $(GTRACE_SRC:%.c=$(BUILD)/obj-lto/%.o)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/bin/gtrace: $(LTO_OBJ) $(GTRACE_LTO_LIB) | $(OIIO_SO) $(OCIO_CONFIG)
	@mkdir -p $(dir $@)
	$(CC) -rdynamic $(LTO) $(OPT) -g -Wno-error=maybe-uninitialized -o $@ $(LTO_OBJ) \
	    -Wl,--whole-archive $(GTRACE_LTO_LIB) -Wl,--no-whole-archive $(LDFLAGS) $(GTRACE_DEPLIBS) $(DEPLIBS)
endif

# the POV-Ray comparison and the other benchmarks that run gtrace
.PHONY: bench-pov
bench-pov: $(BUILD)/bin/gtrace $(BUILD)/bench/runstat
	@bench/pov/bench.sh $(BUILD)
$(BUILD)/bench/runstat: bench/pov/runstat.c
	@mkdir -p $(dir $@)
	$(CC) -std=c11 -O2 -Wall -Wextra -Werror -o $@ $<
# the intersection-only limit (bench/pov/isect_limit.c): the tracer's accel_intersect and accel_occluded reached
# through the linker's --wrap, which records the rays a render casts
bench-pov: $(BUILD)/bench/isect_limit
$(BUILD)/obj/bench/pov/isect_limit.o: CPPFLAGS += -Iexamples/gtrace
$(BUILD)/bench/isect_limit: $(BUILD)/obj/bench/pov/isect_limit.o $(GTRACE_LIB) $(LIBA) | $(OIIO_SO)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $< -Wl,--wrap=accel_intersect -Wl,--wrap=accel_occluded $(GTRACE_LIB) $(LIBA) $(LDFLAGS) \
	    $(GTRACE_DEPLIBS) $(DEPLIBS)
.PHONY: bench-dispersion
bench-dispersion: $(BUILD)/bin/gtrace
	@bench/dispersion.sh $(BUILD)
.PHONY: bench-path
bench-path: $(BUILD)/bin/gtrace $(BUILD)/bin/gprobe
	@bench/path.sh $(BUILD)
.PHONY: bench-emissive
bench-emissive: $(BUILD)/bin/gtrace
	@bench/emissive.sh $(BUILD)
.PHONY: bench-lights
bench-lights: $(BUILD)/bin/gtrace
	@bench/lights.sh $(BUILD)
.PHONY: bench-caustics
bench-caustics: $(BUILD)/bin/gtrace $(BUILD)/bin/gprobe
	@bench/caustics.sh $(BUILD)
# the spectrum model's cost against rgb's over grids of 9 to 201 samples (bench/grid_ratios.sh)
.PHONY: bench-grid
bench-grid: $(BUILD)/bin/gtrace
	@bench/grid_ratios.sh 5 $(BUILD)/bin/gtrace
bench: bench-pov bench-dispersion bench-path bench-mpi bench-emissive bench-caustics bench-lights bench-grid
.PHONY: bench-scale
bench-scale: $(BUILD)/bin/gtrace $(BUILD)/bench/runstat
	@bench/scale.sh $(BUILD)
bench: bench-scale
# against Blender Cycles (optional: the script says so and stops when blender is not installed)
.PHONY: bench-cycles
bench-cycles: $(BUILD)/bin/gtrace
	@bench/cycles.sh $(BUILD)
bench: bench-cycles
# gtrace's MPI module (examples/gtrace/distributed/mpi/, distributed/mpi_module.h), built when Open MPI's
# development files are found (pkg-config ompi-c; Debian's libopenmpi-dev). gtrace opens it with dlopen only when
# it runs under mpirun (mpi_load.c), so --help and a render on one machine never map libmpi; without it gtrace still
# builds and --version says so. Found beside gtrace (../lib/generic/) or in the installed PREFIX/lib/generic/.
GTRACE_MPI_LOAD_OBJ := $(call objs_of,examples/gtrace/distributed/mpi_load.o)
$(GTRACE_MPI_LOAD_OBJ): CPPFLAGS += -DGTRACE_MPI_LIBDIR='"$(PREFIX)/lib"'
MPI_CFLAGS := $(shell pkg-config --cflags ompi-c 2>/dev/null)
MPI_LIBS   := $(shell pkg-config --libs ompi-c 2>/dev/null)
ifneq ($(MPI_LIBS),)
GTRACE_MPI_SO := $(BUILD)/lib/generic/gtrace_mpi.so
GTRACE_MPI_NOTE := gtrace_mpi.so (Open MPI $(shell pkg-config --modversion ompi-c))
$(GTRACE_MPI_LOAD_OBJ): CPPFLAGS += -DGTRACE_MPI_BUILT='"$(GTRACE_MPI_NOTE)"'
$(BUILD)/bin/gtrace: | $(GTRACE_MPI_SO)
all: $(GTRACE_MPI_SO)
$(GTRACE_MPI_SO): examples/gtrace/distributed/mpi/transport.c examples/gtrace/distributed/mpi_module.h
	@mkdir -p $(dir $@)
	$(CC) -std=c11 -D_GNU_SOURCE $(OPT) -g -fPIC -shared -fvisibility=hidden $(WARN) $(SANFLAGS) $(MPI_CFLAGS) \
	    -Wl,-z,defs -o $@ $< $(LDFLAGS) $(MPI_LIBS)
.PHONY: install-mpi uninstall-mpi
install: install-mpi
install-mpi: $(GTRACE_MPI_SO)
	install -d $(INST)/lib/generic
	install -m 755 $(GTRACE_MPI_SO) $(INST)/lib/generic/
uninstall: uninstall-mpi
uninstall-mpi:
	rm -f $(INST)/lib/generic/gtrace_mpi.so
endif
.PHONY: bench-mpi
bench-mpi: $(BUILD)/bin/gtrace
	@bench/mpi.sh $(BUILD)
# libgtrace.so: the tracer as a shared object for bindings (python/build.mk): the objects of libgtrace.a (compiled
# -fPIC like every object), linked against libgeneric.so so that a program holds one registry and one allocator.
# It exports only the entry points of embed/render_file.h (GTRACE_EMBED_API); -z defs: everything else resolves in
# libgeneric, Embree, assimp and libc. Found beside libgeneric.so.0 (run path $ORIGIN), in the tree and installed.
GTRACE_SO := $(BUILD)/lib/libgtrace.so
all: $(GTRACE_SO)
$(GTRACE_SO): $(GTRACE_LIB) $(LIBSO)
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-z,defs -Wl,-soname,libgtrace.so -o $@ -Wl,--whole-archive $(GTRACE_LIB) -Wl,--no-whole-archive \
	    -L$(BUILD)/lib -l:libgeneric.so.$(SOVER) -Wl,-rpath,'$$ORIGIN' $(LDFLAGS) $(GTRACE_DEPLIBS) $(DEPLIBS)
.PHONY: install-gtrace-so uninstall-gtrace-so
install: install-gtrace-so
install-gtrace-so: $(GTRACE_SO)
	install -d $(INST)/lib
	install -m 755 $(GTRACE_SO) $(INST)/lib/
uninstall: uninstall-gtrace-so
uninstall-gtrace-so:
	rm -f $(INST)/lib/libgtrace.so

# The OpenVDB reader of grid media (examples/gtrace/media/vdb/, media/grid_load.c): a program of its own that gtrace
# starts for each grid file, so that OpenVDB (C++, not hardened against hostile files) never runs in gtrace. Built
# without the sanitizers (it runs as a separate process under its own limits) when OpenVDB is installed; without it
# grid media are refused with a message naming the reader.
GTRACE_VDB_READER := $(BUILD)/lib/generic/gtrace-vdb
ifneq ($(wildcard /usr/include/openvdb/openvdb.h),)
all: $(GTRACE_VDB_READER)
$(GTRACE_TEST_BIN) $(BUILD)/bin/gtrace: | $(GTRACE_VDB_READER)
.PHONY: install-vdb-reader uninstall-vdb-reader
install: install-vdb-reader
install-vdb-reader: $(GTRACE_VDB_READER)
	install -d $(INST)/lib/generic
	install -m 755 $(GTRACE_VDB_READER) $(INST)/lib/generic/
uninstall: uninstall-vdb-reader
uninstall-vdb-reader:
	rm -f $(INST)/lib/generic/gtrace-vdb
endif
$(GTRACE_VDB_READER): examples/gtrace/media/vdb/vdb_read.cpp examples/gtrace/media/vdb_protocol.h
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Werror -o $@ $< -lopenvdb -ltbb -lImath-3_1

# The cloud example: the OpenVDB file written by make_grid.py (python3-openvdb), the scene beside it, its image.
VDB_PYTHON ?= $(shell python3 -c 'import pyopenvdb' 2>/dev/null && echo python3 || echo /usr/bin/python3)
.PHONY: media-cloud bench-media
media-cloud: $(BUILD)/bin/gtrace $(GTRACE_VDB_READER)
	@mkdir -p $(BUILD)/media
	$(VDB_PYTHON) examples/gtrace/media/vdb/make_grid.py cloud $(BUILD)/media/cloud.vdb 64
	cp examples/gtrace/media/vdb/media_cloud.scene $(BUILD)/media/
	$(BUILD)/bin/gtrace $(BUILD)/media/media_cloud.scene --integrator path -o $(BUILD)/media/media_cloud.png
bench-media: $(BUILD)/bin/gtrace $(GTRACE_VDB_READER)
	@bench/media.sh $(BUILD)

# The mesh reader (examples/gtrace/geometry/mesh_reader/, geometry/mesh_isolated.c): a program of its own that gtrace
# starts for each PLY, STL or glTF file, so that assimp runs under limits outside gtrace. Built beside the image
# decoder (BUILD/lib/generic/) and installed beside it; found from gtrace, libgtrace.so and the test programs.
GTRACE_MESH_READER := $(BUILD)/lib/generic/gtrace-mesh
GTRACE_MESH_ISOLATED_OBJ := $(call objs_of,examples/gtrace/geometry/mesh_isolated.o)
$(GTRACE_MESH_ISOLATED_OBJ): CPPFLAGS += -DGTRACE_MESH_LIBDIR='"$(PREFIX)/lib"'
all: $(GTRACE_MESH_READER)
$(GTRACE_TEST_BIN) $(BUILD)/bin/gtrace $(GTRACE_SO): | $(GTRACE_MESH_READER)
$(GTRACE_MESH_READER): $(BUILD)/obj/examples/gtrace/geometry/mesh_reader/gtrace_mesh.o $(GTRACE_LIB) $(LIBA)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $(filter %.o,$^) $(GTRACE_LIB) $(LIBA) $(LDFLAGS) -Wl,--as-needed $(GTRACE_DEPLIBS) $(DEPLIBS)
.PHONY: install-mesh-reader uninstall-mesh-reader
install: install-mesh-reader
install-mesh-reader: $(GTRACE_MESH_READER)
	install -d $(INST)/lib/generic
	install -m 755 $(GTRACE_MESH_READER) $(INST)/lib/generic/
uninstall: uninstall-mesh-reader
uninstall-mesh-reader:
	rm -f $(INST)/lib/generic/gtrace-mesh
# bench/bench_mesh_decode.c reads meshes with the tracer's library (bench/build.mk links libgeneric alone)
$(BUILD)/obj/bench/bench_mesh_decode.o: CPPFLAGS += -Iexamples/gtrace
$(BUILD)/bench/bench_mesh_decode: $(GTRACE_LIB) | $(GTRACE_MESH_READER)
$(BUILD)/bench/bench_mesh_decode: DEPLIBS := $(GTRACE_LIB) $(LIBA) $(GTRACE_DEPLIBS) $(DEPLIBS)
.PHONY: bench-media-noise
bench-media-noise: $(BUILD)/bin/gtrace $(BUILD)/bin/gprobe
	@bench/media_noise.sh $(BUILD)
.PHONY: bench-media-equiangular
bench-media-equiangular: $(BUILD)/bin/gtrace $(BUILD)/bin/gprobe
	@bench/media_equiangular.sh $(BUILD)
