# SPDX-License-Identifier: GPL-3.0-or-later
# The library's errors come back as exceptions carrying its message.
import pytest

import hybounce
from conftest import cli


def test_a_bad_value_raises_the_message_the_cli_prints():
    run = hybounce.Run("steel-on-bitumen")
    with pytest.raises(hybounce.InputError) as e:
        run.set("law.c", "44 kg")
    msg = str(e.value)
    assert msg.startswith("law.c: ") and "accepted: " in msg
    assert e.value.status == hybounce.lib.HB_EINVAL and isinstance(e.value, ValueError)
    p = cli("--batch", "steel-on-bitumen", "--set", "law.c=44 kg", check=False)
    assert p.returncode == 2 and msg in p.stderr


def test_an_unknown_key_names_the_keys_accepted():
    with pytest.raises(hybounce.InputError, match=r"law\.nope.*accepted"):
        hybounce.Run("steel-on-bitumen").set("law.nope", 1.0)
    with pytest.raises(hybounce.InputError, match="law.nope"):
        hybounce.Run("steel-on-bitumen").get("law.nope")


def test_an_unknown_preset_says_where_it_looked():
    with pytest.raises(hybounce.InputError, match="no-such-preset.*presets"):
        hybounce.Run("no-such-preset")
    with pytest.raises(hybounce.InputError, match=r"--set ARG|run\.T"):
        hybounce.Run("steel-on-bitumen", {"run.T": "-1 s"})


def test_a_save_that_cannot_write_raises_file_error(tmp_path):
    with pytest.raises(hybounce.FileError, match=str(tmp_path / "none")):
        hybounce.Run("steel-on-bitumen").save(tmp_path / "none" / "x.preset")


def test_a_bad_sweep_or_fit_raises_with_the_message():
    with pytest.raises(hybounce.InputError, match="initial.v0"):
        hybounce.sweep("steel-on-bitumen", {"initial.v0": "1:2:x"})
    with pytest.raises(hybounce.InputError, match="law.nope"):
        hybounce.fit("steel-on-bitumen", [0.05, 0.13, 0.2], ["law.nope"])


def test_a_sweep_with_a_bad_point_raises_naming_it():
    # each point is validated once, where it runs: the error names the point
    with pytest.raises(hybounce.InputError, match=r"point 1 \(law\.beta=1000000000 law\.gamma=2000000000\): law\.gamma"):
        hybounce.sweep("permanent-contact-bwshccl", ["law.beta=5e9,1e9", "law.gamma=2e9"], jobs=1)


def test_reading_before_a_run_is_an_error():
    with pytest.raises(hybounce.HybounceError, match="run()"):
        hybounce.Run("steel-on-bitumen").collisions


def test_a_numerical_failure_raises_and_keeps_what_was_computed():
    run = hybounce.Run("steel-on-bitumen", {"run.h_max": "1e-300"})
    with pytest.raises(hybounce.NumericError) as e:
        run.run()
    p = cli("--batch", "steel-on-bitumen", "--set", "run.h_max=1e-300", check=False)
    assert p.returncode == 1 and str(e.value) in p.stderr and "t = " in str(e.value)
    assert run.failed and len(run.arc) >= 2 and "failed" in repr(run)
