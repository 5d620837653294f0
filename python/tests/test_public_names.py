"""The package's public names are its API alone: its imports (numpy, typing,
dataclasses, ...) are private, so dir(), tab completion and `import *` show
only what __all__ lists."""

import inspect
import typing

import pytest

import unfold
import unfold.metrics


@pytest.mark.parametrize("module", [unfold, unfold.metrics], ids=lambda m: m.__name__)
def test_the_public_names_are_all_and_all_exist(module):
    public = [name for name in dir(module) if not name.startswith("_")]
    assert public == sorted(module.__all__)
    missing = [name for name in module.__all__ if not hasattr(module, name)]
    assert missing == []


@pytest.mark.parametrize("module", [unfold, unfold.metrics], ids=lambda m: m.__name__)
def test_the_annotations_still_resolve(module):
    # They name the private imports (_np.ndarray): typing resolves them in the module.
    for name in module.__all__:
        value = getattr(module, name)
        if inspect.isfunction(value) or getattr(value, "__module__", None) == module.__name__:
            typing.get_type_hints(value)
