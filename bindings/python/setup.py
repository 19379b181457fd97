"""Builds the carom C library (C99 + libm, the same sources as the
Makefile's) into the package, as carom/_libcarom*.so, which carom/_native.py
loads first.

The C sources come from csrc/ when it is there (an sdist carries them:
see the sdist command below), else from the repository this directory sits
in (../../lib, ../../include). The version is the header's
(CAROM_VERSION_MAJOR, _MINOR, _PATCH in include/carom.h): one place.
"""

import glob
import os
import re
import shutil

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.sdist import sdist

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, os.pardir, os.pardir))


def c_root():
    """Where lib/ and include/ are: csrc/ in an sdist, else the repository."""
    for root in (os.path.join(HERE, "csrc"), REPO):
        if os.path.isfile(os.path.join(root, "include", "carom.h")) and glob.glob(
                os.path.join(root, "lib", "*.c")):
            return root
    raise SystemExit("carom: the C sources (lib/*.c, include/carom.h) are neither in csrc/ "
                     "nor in the repository around %s" % HERE)


def header_version(root):
    text = open(os.path.join(root, "include", "carom.h"), encoding="utf-8").read()
    parts = [re.search(r"#define CAROM_VERSION_%s (\d+)" % k, text).group(1)
             for k in ("MAJOR", "MINOR", "PATCH")]
    return ".".join(parts)


ROOT = c_root()
# The library's own flags: C99, no fused multiply-add (the same bits as the
# Makefile's build, docs/reliability.md), only the carom_* API exported.
CFLAGS = ["-std=c99", "-O3", "-ffp-contract=off", "-fvisibility=hidden"]


class build_c_library(build_ext):
    """The extension is a plain C shared library, loaded with ctypes, not
    imported: it has no PyInit function and needs none. Its sources lie
    outside this directory (the repository's lib/), which setuptools' own
    source list may not name, so they are compiled here."""

    def get_export_symbols(self, ext):
        return []

    def build_extension(self, ext):
        sources = sorted(glob.glob(os.path.join(ROOT, "lib", "*.c")))
        objects = self.compiler.compile(
            sources, output_dir=self.build_temp,
            include_dirs=[os.path.join(ROOT, "include"), os.path.join(ROOT, "lib")],
            extra_postargs=CFLAGS)
        self.compiler.link_shared_object(objects, self.get_ext_fullpath(ext.name),
                                         libraries=["m"], target_lang="c")


class sdist_with_c(sdist):
    """Copy the C sources into csrc/ so the sdist builds anywhere."""

    def run(self):
        target = os.path.join(HERE, "csrc")
        made = False
        if ROOT == REPO:
            shutil.rmtree(target, ignore_errors=True)
            for sub in ("lib", "include"):
                shutil.copytree(os.path.join(REPO, sub), os.path.join(target, sub),
                                ignore=shutil.ignore_patterns("*.o", "*.d"))
            made = True
        try:
            sdist.run(self)
        finally:
            if made:
                shutil.rmtree(target, ignore_errors=True)


setup(
    version=header_version(ROOT),
    ext_modules=[Extension("carom._libcarom", sources=[])],
    cmdclass={"build_ext": build_c_library, "sdist": sdist_with_c},
)
