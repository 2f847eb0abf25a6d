# examples/build.mk - the tools (examples/NAME/ with a main.c: build/bin/NAME) and the example plug-ins
# (examples/plugins/*.c, one module each: build/plugins/NAME.so), and their installation with a man page per tool.

.PHONY: tools plugins install-tools uninstall-tools
TOOLS    := $(notdir $(patsubst %/,%,$(dir $(wildcard examples/*/main.c))))
TOOL_BIN := $(TOOLS:%=$(BUILD)/bin/%)
tools: $(TOOL_BIN)

# the tools' --version (examples/common/cli.h)
$(call objs_of,examples/%.o): CPPFLAGS += -DGENERIC_VERSION='"$(VERSION)"'

# A tool is every .c of its folder, linked with the library (LINK_PROGRAM, lib/build.mk) and EXTRA_LIBS_<tool>.
tool_obj = $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard examples/$(1)/*.c))
$(BUILD)/bin/%: $$(call tool_obj,$$*) $(LIBA) | $(OIIO_SO) $(OCIO_CONFIG)
	@mkdir -p $(dir $@)
	$(LINK_PROGRAM) $(EXTRA_LIBS_$*) $(DEPLIBS)

# Objects that only a pattern rule names are intermediate to make, which would delete them after linking and
# compile them again on the next goal (`make demo` then `make test`).
.SECONDARY: $(foreach t,$(TOOLS),$(call tool_obj,$(t)))

EXAMPLE_PLUGIN_SO := $(patsubst examples/plugins/%.c,$(BUILD)/plugins/%.so,$(wildcard examples/plugins/*.c))
plugins: $(EXAMPLE_PLUGIN_SO)
$(EXAMPLE_PLUGIN_SO): $(BUILD)/plugins/%.so: examples/plugins/%.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -o $@ $< -lm

# install: the tools (bin/), the example plug-ins (PLUGIN_DIR) and, when help2man is installed, a man page per tool
# made from its --help and --version (MAN_NAME_<tool>: its NAME line).
MAN_NAME_gcolor := sample colours in every colour model of libgeneric
MAN_NAME_gmat   := evaluate, check, list and plot the materials and texture trees of a libgeneric file
MAN_NAME_gprobe := approximate an HDR light probe by lights and compare the techniques
MAN_NAME_gtrace := render a libgeneric scene file
install: install-tools
install-tools: tools $(EXAMPLE_PLUGIN_SO)
	install -d $(INST)/bin $(DESTDIR)$(PLUGIN_DIR)
	install -m 755 $(TOOL_BIN) $(INST)/bin/
	install -m 755 $(EXAMPLE_PLUGIN_SO) $(DESTDIR)$(PLUGIN_DIR)/
	@if command -v help2man >/dev/null 2>&1; then \
	    install -d $(DESTDIR)$(MAN_DIR) && \
	    $(foreach t,$(TOOLS),echo "help2man $(BUILD)/bin/$(t) > $(DESTDIR)$(MAN_DIR)/$(t).1" && \
	    help2man -N -n "$(or $(MAN_NAME_$(t)),a libgeneric tool)" -o $(DESTDIR)$(MAN_DIR)/$(t).1 $(BUILD)/bin/$(t) &&) \
	    true; \
	else echo "install: help2man not found: no man pages written (Debian package help2man)"; fi

uninstall: uninstall-tools
uninstall-tools:
	rm -f $(addprefix $(INST)/bin/,$(TOOLS)) $(addprefix $(DESTDIR)$(MAN_DIR)/,$(TOOLS:=.1))
	rm -f $(addprefix $(DESTDIR)$(PLUGIN_DIR)/,$(notdir $(EXAMPLE_PLUGIN_SO)))

# libgmat.so: `gmat check` for bindings (python/build.mk): gmat's checking objects and check_file.c, linked against
# libgeneric.so (one registry with the program); exports only check_file.h's entry point. -z defs: gmat's command
# line (main.c and the commands it alone runs) is not part of it.
GMAT_SO := $(BUILD)/lib/libgmat.so
GMAT_SO_OBJ := $(patsubst %,$(BUILD)/obj/examples/gmat/%.o,albedo check check_file flags measure sampling uvflag \
               relindex constindex clear)
all: $(GMAT_SO)
$(GMAT_SO): $(GMAT_SO_OBJ) $(LIBSO)
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-z,defs -Wl,-soname,libgmat.so -o $@ $(GMAT_SO_OBJ) -L$(BUILD)/lib -l:libgeneric.so.$(SOVER) \
	    -Wl,-rpath,'$$ORIGIN' $(LDFLAGS) $(DEPLIBS)
.PHONY: install-gmat-so uninstall-gmat-so
install: install-gmat-so
install-gmat-so: $(GMAT_SO)
	install -d $(INST)/lib
	install -m 755 $(GMAT_SO) $(INST)/lib/
uninstall: uninstall-gmat-so
uninstall-gmat-so:
	rm -f $(INST)/lib/libgmat.so
