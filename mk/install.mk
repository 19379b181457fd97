# Installation, GNU style (docs/abi.md, docs/bindings.md):
#   make install   [PREFIX=/usr/local] [DESTDIR=staging-root]
#   make uninstall [PREFIX=/usr/local] [DESTDIR=staging-root]
#   make check-install   tests/test_install.sh (a staged install, used
#                        through pkg-config by a small C program)
# Installs include/carom.h, libcarom.so.$(VERSION) with its soname link
# $(SONAME) and the development link libcarom.so, libcarom.a, a carom.pc
# generated from carom.pc.in, a CMake package (carom-config.cmake and its
# version file, from cmake/, in $(LIBDIR)/cmake/carom: find_package(carom)),
# the scenes in $(DATADIR)/carom/scenes and, when Cairo is there to build
# it, the headless runner `carom` in $(BINDIR). LIBDIR and INCLUDEDIR may be
# set on their own (LIBDIR=/usr/lib/x86_64-linux-gnu for a Debian multiarch
# layout).

PREFIX       ?= /usr/local
DESTDIR      ?=
LIBDIR       ?= $(PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
CMAKEDIR     ?= $(LIBDIR)/cmake/carom
BINDIR       ?= $(PREFIX)/bin
DATADIR      ?= $(PREFIX)/share
INSTALL      ?= install
LDCONFIG     ?= ldconfig

# carom.pc names its directories relative to ${prefix} where it can, so a
# relocated tree (PKG_CONFIG_SYSROOT_DIR, --define-prefix) still works.
pc_rel = $(patsubst $(PREFIX)/%,$${prefix}/%,$(1))

.PHONY: install uninstall check-install

$(BUILD)/carom.pc: carom.pc.in Makefile mk/install.mk FORCE_PC
	@mkdir -p $(@D)
	@sed -e 's|@PREFIX@|$(PREFIX)|g' \
	    -e 's|@LIBDIR@|$(call pc_rel,$(LIBDIR))|g' \
	    -e 's|@INCLUDEDIR@|$(call pc_rel,$(INCLUDEDIR))|g' \
	    -e 's|@VERSION@|$(VERSION)|g' carom.pc.in >$@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

# The CMake package names its directories relative to its own, so a staged
# or moved install works.
rel_path = $(shell realpath -m --relative-to=$(1) $(2))
$(BUILD)/cmake/%.cmake: cmake/%.cmake.in Makefile mk/install.mk FORCE_PC
	@mkdir -p $(@D)
	@sed -e 's|@CMAKE_TO_PREFIX@|$(call rel_path,$(CMAKEDIR),$(PREFIX))|g' \
	    -e 's|@LIBDIR_REL@|$(call rel_path,$(PREFIX),$(LIBDIR))|g' \
	    -e 's|@INCLUDEDIR_REL@|$(call rel_path,$(PREFIX),$(INCLUDEDIR))|g' \
	    -e 's|@VERSION_MAJOR@|$(VERSION_MAJOR)|g' -e 's|@VERSION@|$(VERSION)|g' $< >$@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

# The runner needs Cairo; without it the library is installed alone.
HAVE_CAIRO = $(shell pkg-config --exists cairo 2>/dev/null && echo yes)
SCENE_FILES := $(wildcard scenes/*.scene)

# PREFIX may differ from one call to the next: regenerate carom.pc each time
# (it is only rewritten when its text changes).
.PHONY: FORCE_PC
FORCE_PC:

install: $(BUILD)/libcarom.a $(BUILD)/libcarom.so $(BUILD)/carom.pc $(BUILD)/cmake/carom-config.cmake \
         $(BUILD)/cmake/carom-config-version.cmake $(if $(HAVE_CAIRO),$(BUILD)/carom)
	$(INSTALL) -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) $(DESTDIR)$(CMAKEDIR) \
	  $(DESTDIR)$(DATADIR)/carom/scenes
	$(INSTALL) -m 644 include/carom.h $(DESTDIR)$(INCLUDEDIR)/carom.h
	$(INSTALL) -m 755 $(SO_REAL) $(DESTDIR)$(LIBDIR)/libcarom.so.$(VERSION)
	ln -sf libcarom.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libcarom.so
	$(INSTALL) -m 644 $(BUILD)/libcarom.a $(DESTDIR)$(LIBDIR)/libcarom.a
	$(INSTALL) -m 644 $(BUILD)/carom.pc $(DESTDIR)$(PKGCONFIGDIR)/carom.pc
	$(INSTALL) -m 644 $(BUILD)/cmake/carom-config.cmake $(BUILD)/cmake/carom-config-version.cmake $(DESTDIR)$(CMAKEDIR)
	$(INSTALL) -m 644 $(SCENE_FILES) $(DESTDIR)$(DATADIR)/carom/scenes
	@if [ -n "$(HAVE_CAIRO)" ]; then \
	  $(INSTALL) -d $(DESTDIR)$(BINDIR) && $(INSTALL) -m 755 $(BUILD)/carom $(DESTDIR)$(BINDIR)/carom; \
	else echo "install: the runner needs Cairo (apt-get install libcairo2-dev): not installed"; fi
	@if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" -eq 0 ] && command -v $(LDCONFIG) >/dev/null 2>&1; then \
	  $(LDCONFIG) || true; fi
	@echo "install: carom $(VERSION) installed in $(DESTDIR)$(PREFIX)"

uninstall:
	rm -f $(DESTDIR)$(INCLUDEDIR)/carom.h
	rm -f $(DESTDIR)$(LIBDIR)/libcarom.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	rm -f $(DESTDIR)$(LIBDIR)/libcarom.so $(DESTDIR)$(LIBDIR)/libcarom.a
	rm -f $(DESTDIR)$(PKGCONFIGDIR)/carom.pc
	rm -f $(DESTDIR)$(CMAKEDIR)/carom-config.cmake $(DESTDIR)$(CMAKEDIR)/carom-config-version.cmake
	rm -f $(DESTDIR)$(BINDIR)/carom $(SCENE_FILES:scenes/%=$(DESTDIR)$(DATADIR)/carom/scenes/%)
	-rmdir $(DESTDIR)$(CMAKEDIR) $(DESTDIR)$(DATADIR)/carom/scenes $(DESTDIR)$(DATADIR)/carom 2>/dev/null
	@echo "uninstall: carom removed from $(DESTDIR)$(PREFIX)"

check-install: $(BUILD)/libcarom.a $(BUILD)/libcarom.so
	@MAKE="$(MAKE)" sh tests/test_install.sh $(BUILD)
