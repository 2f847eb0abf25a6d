# tests/build.mk - the test programs (tests/test_*.c: build/tests/test_*), the test plug-ins (one source built once
# per variant) and the built-in type files built as run-time modules. scripts/run_tests.sh runs them.

.PHONY: tests modules
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TESTLIBS := $(shell pkg-config --libs cmocka 2>/dev/null)
tests: $(TEST_BIN)

# Tests of a tool's own code link its objects too (TEST_OBJ_<test>).
TEST_OBJ_test_fluorescent := $(BUILD)/obj/examples/gmat/laser_experiment.o
TEST_OBJ_test_fluorescent_laser := $(BUILD)/obj/examples/gmat/laser_experiment.o
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $$(TEST_OBJ_$$*) $(LIBA) | $(OIIO_SO) $(OCIO_CONFIG)
	@mkdir -p $(dir $@)
	$(LINK_PROGRAM) $(TESTLIBS) $(DEPLIBS)
.SECONDARY: $(TEST_SRC:%.c=$(BUILD)/obj/%.o)

# ---- test plug-ins: NAME:SOURCE:DEFINE builds tests/plugins/SOURCE.c with -DDEFINE into BUILD/plugins/NAME.so ----
# bad_module.c, for tests/test_plugin.c: a wrong interface version, a failing init, no entry point, a constructor
# but no module. nonconforming.c, for tests/scripts/conformance.sh: an albedo above 1, a material that is not
# reciprocal, a sampler that disagrees with its pdf, a glow hidden by a wrong GMAT_NO_EMISSION, a transparency
# hidden by a wrong GMAT_OPAQUE, a tilted normal hidden by a wrong GMAT_GEOMETRIC_NORMAL, a diffuse colour that a
# wrong GMAT_LAMBERTIAN renders in place of the reflection, a reflection that reads u under a wrong GMAT_NO_UV, a
# grey response to coloured light under a wrong GMAT_DIAGONAL, a wrong colour add, overlapping wavelength bands;
# and for tests/scripts/bump_ideal_conformance.sh: a mirror reflecting 1.2 times the light, a glass refracting
# about the geometric normal, a mirror reflecting light from inside the body. halfvector.c, for
# tests/scripts/check_gaps.sh: a correct GGX sampler whose pdf has an integrable singularity.
TEST_PLUGINS := bad_abi:bad_module:BAD_ABI failing_init:bad_module:FAIL_INIT no_init:bad_module:NO_INIT \
                constructor_only:bad_module:NOT_A_MODULE \
                gain:nonconforming:GAIN skewed:nonconforming:SKEWED misdrawn:nonconforming:MISDRAWN \
                misflagged:nonconforming:MISFLAGGED misopaque:nonconforming:MISOPAQUE \
                misnormal:nonconforming:MISNORMAL misdiffuse:nonconforming:MISDIFFUSE misuv:nonconforming:MISUV \
                misdiag:nonconforming:MISDIAG misideal:nonconforming:MISIDEAL bad_add:nonconforming:BAD_ADD \
                misrelindex:nonconforming:MISRELINDEX misconstindex:nonconforming:MISCONSTINDEX \
                misclear:nonconforming:MISCLEAR \
                bad_bands:nonconforming:BAD_BANDS \
                gain_mirror:nonconforming:GAIN_MIRROR misbent:nonconforming:MISBENT leaky:nonconforming:LEAKY \
                halfvector:halfvector:GGX
# test_plugin NAME: "NAME SOURCE DEFINE"
test_plugin = $(subst :, ,$(filter $(1):%,$(TEST_PLUGINS)))
TEST_PLUGIN_SO := $(foreach p,$(TEST_PLUGINS),$(BUILD)/plugins/$(firstword $(subst :, ,$(p))).so)
plugins: $(TEST_PLUGIN_SO) modules
$(TEST_PLUGIN_SO): $(BUILD)/plugins/%.so: tests/plugins/$$(word 2,$$(call test_plugin,$$*)).c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -D$(word 3,$(call test_plugin,$*)) -o $@ $< -lm

# ---- built-in files as run-time modules: the proof that a type's file is self-contained ----
# Each file of BUILTIN_MODULES is compiled as it is in the tree, plus the one line `GENERIC_MODULE(&gtype_NAME);`
# (NAME: the file's base name), into BUILD/modules/NAME.so: against the installed headers only, not linked with
# libgeneric, its own symbols hidden (PLUGIN_CFLAGS) so that none binds to the program's built-in copy.
# tests/test_builtin_modules.c loads them into a registry that lacks those built-ins.
BUILTIN_MODULES := materials/lambert.c colormodels/rgb.c
MODULE_SO := $(patsubst %.c,$(BUILD)/modules/%.so,$(notdir $(BUILTIN_MODULES)))
modules: $(MODULE_SO)
.SECONDARY: $(MODULE_SO:%.so=%_module.c)

$(BUILD)/modules/%_module.c: $$(filter $$(PERCENT)/$$*.c,$(BUILTIN_MODULES))
	@mkdir -p $(dir $@)
	{ cat $<; echo; echo 'GENERIC_MODULE(&gtype_$*);'; } > $@
PERCENT := %

$(BUILD)/modules/%.so: $(BUILD)/modules/%_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -o $@ $< -lm

# Tests that read images start the image decoder process (lib/build.mk).
$(TEST_BIN): | $(DECODER)
