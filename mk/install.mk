# Installation, GNU style (docs/abi.md, docs/bindings.md):
#   make install   [PREFIX=/usr/local] [DESTDIR=staging-root]
#   make uninstall [PREFIX=/usr/local] [DESTDIR=staging-root]
#   make check-install   tests/test_install.sh (a staged install, used
#                        through pkg-config by a small C program)
# Installs include/carom.h, libcarom.so.$(VERSION) with its soname link
# $(SONAME) and the development link libcarom.so, libcarom.a, and a carom.pc
# generated from carom.pc.in. LIBDIR and INCLUDEDIR may be set on their own
# (LIBDIR=/usr/lib/x86_64-linux-gnu for a Debian multiarch layout).

PREFIX       ?= /usr/local
DESTDIR      ?=
LIBDIR       ?= $(PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
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

# PREFIX may differ from one call to the next: regenerate carom.pc each time
# (it is only rewritten when its text changes).
.PHONY: FORCE_PC
FORCE_PC:

install: $(BUILD)/libcarom.a $(BUILD)/libcarom.so $(BUILD)/carom.pc
	$(INSTALL) -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR)
	$(INSTALL) -m 644 include/carom.h $(DESTDIR)$(INCLUDEDIR)/carom.h
	$(INSTALL) -m 755 $(SO_REAL) $(DESTDIR)$(LIBDIR)/libcarom.so.$(VERSION)
	ln -sf libcarom.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libcarom.so
	$(INSTALL) -m 644 $(BUILD)/libcarom.a $(DESTDIR)$(LIBDIR)/libcarom.a
	$(INSTALL) -m 644 $(BUILD)/carom.pc $(DESTDIR)$(PKGCONFIGDIR)/carom.pc
	@if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" -eq 0 ] && command -v $(LDCONFIG) >/dev/null 2>&1; then \
	  $(LDCONFIG) || true; fi
	@echo "install: carom $(VERSION) installed in $(DESTDIR)$(PREFIX)"

uninstall:
	rm -f $(DESTDIR)$(INCLUDEDIR)/carom.h
	rm -f $(DESTDIR)$(LIBDIR)/libcarom.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	rm -f $(DESTDIR)$(LIBDIR)/libcarom.so $(DESTDIR)$(LIBDIR)/libcarom.a
	rm -f $(DESTDIR)$(PKGCONFIGDIR)/carom.pc
	@echo "uninstall: carom removed from $(DESTDIR)$(PREFIX)"

check-install: $(BUILD)/libcarom.a $(BUILD)/libcarom.so
	@MAKE="$(MAKE)" sh tests/test_install.sh $(BUILD)
