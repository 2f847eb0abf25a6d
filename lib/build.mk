# lib/build.mk - the library (static and shared), its OpenImageIO module, the generated sources, the shipped
# OpenColorIO config, the uninstalled generic.pc, the public headers as modules see them, and their installation.
# Included by the top Makefile, which names the sources (LIB_SRC, LIB_CXX) and the products (LIBA, LIBSO, OIIO_SO).

.PHONY: lib install-lib uninstall-lib
lib: $(LIBA) $(LIBSO) $(OIIO_SO) $(OCIO_CONFIG) $(BUILD)/pkgconfig/generic.pc

# Where `make install` puts the module: the loader's last resort when it is not beside the library.
$(call objs_of,lib/image/oiio_loader.o): CPPFLAGS += -DGENERIC_LIBDIR='"$(PREFIX)/lib"'
$(call objs_of,lib/image/decode_isolated.o): CPPFLAGS += -DGENERIC_LIBDIR='"$(PREFIX)/lib"'
# Where `make install` puts the shipped OpenColorIO config (share/ocio/config.ocio); the build tree has it in
# $(BUILD)/share/generic/ocio/, found beside the programs the same way (lib/image/image_display.c).
$(call objs_of,lib/image/image_display.o): CPPFLAGS += -DGENERIC_DATADIR='"$(PREFIX)/share"'
$(call objs_of,lib/module/plugin.o): CPPFLAGS += -DGENERIC_PLUGIN_DIR='"$(PLUGIN_DIR)"'
# The Fresnel kernels: square roots as instructions (no errno) and divisions that may be computed on lanes a branch
# would skip (no trapping math), so that their loops vectorise.
$(call objs_of,lib/kit/fresnel.o): CFLAGS += -fno-math-errno -fno-trapping-math

# ---- generated sources, for any build tree (BUILD, the fuzzing build) ----
# The list of built-in types (include/generic/builtins.h), from the GENERIC_TYPE records of LIB_SRC.
%/gen/builtin_types.c: $(LIB_SRC) $(wildcard $(addsuffix listing_order,$(TYPE_DIRS))) scripts/gen_builtins.sh
	@mkdir -p $(dir $@)
	@scripts/gen_builtins.sh $@ $(LIB_SRC)

# The extensions OpenImageIO writes (gimage_write_extensions, generic/services/image.h), found at build time by a
# small program built against OpenImageIO, so that --help lists them without loading it.
%/gen/image_writers.c: $(BUILD)/gen/gen_image_writers
	@mkdir -p $(dir $@)
	$< $@

.PRECIOUS: %/gen/builtin_types.c %/gen/image_writers.c %/gen/uplift_tables.c

# The sigmoid uplifting tables (include/generic/colorspace.h), fitted at build time by a small program on the
# library's CIE tables: UPLIFT_RES nodes per axis, three spaces of three slices each.
UPLIFT_RES ?= 32
UPLIFT_GEN_SRC := scripts/gen_uplift_tables.c lib/color/uplift_fit.c lib/color/colorspace.c lib/color/cie_tables.c
%/gen/uplift_tables.c: $(BUILD)/gen/gen_uplift_tables
	@mkdir -p $(dir $@)
	$< $(UPLIFT_RES) $@

# built without the sanitizers: it runs at build time, and OpenImageIO's own leaks are no concern there
$(BUILD)/gen/gen_image_writers: scripts/gen_image_writers.cpp
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O1 $(shell pkg-config --cflags OpenImageIO 2>/dev/null) $< -o $@ $(OIIO_LIBS)

# built without the sanitizers and optimised: it runs at build time, for a few seconds
$(BUILD)/gen/gen_uplift_tables: $(UPLIFT_GEN_SRC) lib/color/uplift_fit.h lib/color/uplift_tables.h \
                                lib/color/colorspace_matrix.h lib/color/cie_tables.h include/generic/colorspace.h
	@mkdir -p $(dir $@)
	$(CC) -std=c11 -O2 -D_GNU_SOURCE -Iinclude -Ilib $(WARN) $(UPLIFT_GEN_SRC) -o $@ -lm -pthread

# ---- the library, its module, its data ----
$(LIBA): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(LIBSO): $(LIB_OBJ) lib/libgeneric.map
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-soname,libgeneric.so.$(SOVER) -Wl,--version-script=lib/libgeneric.map -o $@ $(filter %.o,$^) \
	    $(LDFLAGS) $(DEPLIBS)
	ln -sf libgeneric.so.$(SOVER) $(BUILD)/lib/libgeneric.so

# Linked with OpenImageIO only (-z defs: every symbol it uses resolves there; the library's functions come in the
# host table), exporting its one entry.
$(OIIO_SO): $(OIIO_OBJ) lib/image/oiio_module.map
	@mkdir -p $(dir $@)
	$(CXX) -shared -Wl,-z,defs -Wl,--version-script=lib/image/oiio_module.map -o $@ $(filter %.o,$^) $(LDFLAGS) \
	    $(OIIO_LIBS)

$(OCIO_CONFIG): share/ocio/config.ocio
	@mkdir -p $(dir $@)
	cp $< $@

# A program of the tree (a tool, a test) links the whole static library, so that it runs from the build tree
# without LD_LIBRARY_PATH and plug-ins find all of the library's symbols in it (-rdynamic).
LINK_PROGRAM = $(CC) -rdynamic -o $@ $(filter %.o,$^) -Wl,--whole-archive $(LIBA) -Wl,--no-whole-archive $(LDFLAGS)

# ---- generic.pc: installed (PREFIX) and uninstalled (this tree's include/ and BUILD/lib) ----
# From a clone, after `make`: PKG_CONFIG_PATH=build/pkgconfig pkg-config --cflags --libs generic. The uninstalled
# file adds a run path to BUILD/lib, so that a program built with it runs without LD_LIBRARY_PATH. It is rewritten
# when its text would change (a moved tree) and left alone otherwise.
# A sanitizer build's library needs the sanitizers' run-time first in the program, so its uninstalled file hands
# their flags to the programs and modules built with it (PC_SANITIZE; empty for the installed file).
pc_text = sed -e 's|@PREFIX@|$(1)|' -e 's|@INCLUDEDIR@|$(2)|' -e 's|@LIBDIR@|$(3)|' -e 's|@RPATH@|$(4)|' \
              -e 's|@SANITIZE@|$(PC_SANITIZE)|' -e 's|@VERSION@|$(VERSION)|' generic.pc.in
PC_SANITIZE :=
$(BUILD)/pkgconfig/generic.pc: PC_SANITIZE = $(if $(SANFLAGS), $(SANFLAGS))
$(BUILD)/pkgconfig/generic.pc: generic.pc.in FORCE
	@mkdir -p $(dir $@)
	@$(call pc_text,$(CURDIR),$(CURDIR)/include,$(abspath $(BUILD)/lib), -Wl$(comma)-rpath$(comma)$${libdir}) > $@.tmp
	@if cmp -s $@.tmp $@; then rm $@.tmp; else mv $@.tmp $@; echo "wrote $@"; fi
comma := ,
.PHONY: FORCE
FORCE:

# ---- the public headers as `make install` lays them out, for the modules built in the tree ----
PLUGIN_HDR := $(patsubst include/generic/%,$(PLUGIN_INC)/generic/%,$(PUBLIC_HDR))
$(PLUGIN_INC)/generic/%.h: include/generic/%.h
	@mkdir -p $(dir $@)
	install -m 644 $< $@

# ---- install: headers, both libraries, the OpenImageIO module, the OpenColorIO config, generic.pc ----
install: install-lib
install-lib: lib
	install -d $(INST)/include/generic/kit $(INST)/include/generic/services $(INST)/lib/pkgconfig \
	    $(INST)/lib/generic $(INST)/share/generic/ocio
	install -m 644 include/generic/*.h $(INST)/include/generic/
	install -m 644 include/generic/kit/*.h $(INST)/include/generic/kit/
	install -m 644 include/generic/services/*.h $(INST)/include/generic/services/
	install -m 644 $(LIBA) $(INST)/lib/
	install -m 755 $(LIBSO) $(INST)/lib/
	ln -sf libgeneric.so.$(SOVER) $(INST)/lib/libgeneric.so
	install -m 755 $(OIIO_SO) $(INST)/lib/generic/
	install -m 755 $(DECODER) $(INST)/lib/generic/
	install -m 644 share/ocio/config.ocio $(INST)/share/generic/ocio/
	$(call pc_text,$(PREFIX),$${prefix}/include,$${exec_prefix}/lib,) > $(INST)/lib/pkgconfig/generic.pc

uninstall: uninstall-lib
uninstall-lib:
	rm -f $(patsubst include/%,$(INST)/include/%,$(PUBLIC_HDR))
	rm -f $(INST)/lib/libgeneric.a $(INST)/lib/libgeneric.so $(INST)/lib/libgeneric.so.$(SOVER)
	rm -f $(INST)/lib/generic/$(notdir $(OIIO_SO)) $(INST)/lib/generic/$(notdir $(DECODER)) \
	    $(INST)/lib/pkgconfig/generic.pc
	rm -f $(INST)/share/generic/ocio/config.ocio

# ---- the image decoder process (lib/image/decode_isolated.c), beside the OpenImageIO module it loads ----
DECODER := $(BUILD)/lib/generic/generic-decode
lib: $(DECODER)
$(DECODER): $(BUILD)/obj/lib/image/decoder/generic_decode.o $(LIBA) | $(OIIO_SO)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $(filter %.o,$^) $(LIBA) $(LDFLAGS) $(DEPLIBS)

# OpenEXRCore is not linked: lib/image/exr_core_lib.c loads it by its soname on the first OpenEXR file written in the
# process (a program that writes none never maps it)
EXRCORE_SONAME := $(shell objdump -p "$$($(CC) -print-file-name=libOpenEXRCore.so)" 2>/dev/null | \
                    sed -n 's/^ *SONAME *//p')
$(call objs_of,lib/image/exr_core_lib.o): \
    CPPFLAGS += $(if $(EXRCORE_SONAME),-DGENERIC_EXRCORE_SONAME='"$(EXRCORE_SONAME)"')
