# SPDX-License-Identifier: GPL-3.0-or-later
# Shared set-up of the Python tests (tests/cli/python.sh runs them): the
# hybounce binary they compare with ($HYBOUNCE_BIN), the presets, the paper
# studies.
import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.environ.get("HYBOUNCE_BIN", os.path.join(ROOT, "build", "hybounce"))
os.environ.setdefault("HYBOUNCE_PRESETS", os.path.join(ROOT, "presets"))

# the paper's five studies (README: Speed and accuracy)
STUDIES = ["steel-on-bitumen", "ptfe-pom", "permanent-contact-shccl",
           "permanent-contact-bwshccl", "permanent-contact-bwmcl"]


def cli(*args, check=True):
    """Runs the hybounce binary; returns the CompletedProcess (text)."""
    p = subprocess.run([BIN] + list(args), capture_output=True, text=True)
    if check and p.returncode != 0:
        raise AssertionError("%s %s exited %d: %s" % (BIN, " ".join(args), p.returncode, p.stderr))
    return p


@pytest.fixture
def bin_path():
    return BIN
