"""Config dictionaries and keyword overrides as the library's overrides.

The library takes {dotted key: YAML value text}; here nested dicts
({"cascade": {"k_iter": 20}}), dotted names ({"cascade.k_iter": 20}) and the
command-line flag names ({"k_iter": 20}) all become that. The key names come
from the library's own list (_core.config_keys()), so new keys work here
without changes; unknown keys are refused by the library, naming the key.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from typing import Any, Union

import numpy as np

from . import _core

# os.PathLike bare: Python 3.8 cannot subscript it, and a string annotation
# inside the alias would be looked up in the module that uses it (unfold).
Config = Union[None, str, os.PathLike, Mapping[str, Any]]

_FLAG_PATHS = {flag: path for flag, path, _ in _core.config_keys()}


def _yaml_text(key: str, value: Any) -> str:
    if isinstance(value, (np.generic, np.ndarray)):
        value = value.tolist()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, (str, os.PathLike)):
        # A double-quoted YAML string; commas escaped, as the library reads
        # a bare "a,b" as a list.
        return json.dumps(os.fspath(value)).replace(",", "\\x2c")
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_yaml_text(key, item) for item in value) + "]"
    raise _core.ConfigError(
        f"config key '{key}' cannot be set to {value!r} (a {type(value).__name__})")


def _flatten(config: Mapping[str, Any], prefix: str, out: dict[str, str]) -> None:
    for name, value in config.items():
        key = f"{prefix}.{name}" if prefix else str(name)
        if isinstance(value, Mapping):
            _flatten(value, key, out)
        else:
            out[_FLAG_PATHS.get(key, key) if not prefix else key] = _yaml_text(key, value)


def overrides(config: Mapping[str, Any] | None, keywords: Mapping[str, Any]) -> dict[str, str]:
    """The library's overrides from a config dict, then keyword overrides."""
    out: dict[str, str] = {}
    _flatten(config or {}, "", out)
    _flatten(keywords, "", out)
    return out


def split(config: Config, keywords: Mapping[str, Any]) -> tuple[str, dict[str, str]]:
    """(YAML file path or "", overrides) for a config argument and keywords."""
    if config is None or isinstance(config, Mapping):
        return "", overrides(config, keywords)
    if isinstance(config, (str, os.PathLike)):
        return os.fspath(config), overrides(None, keywords)
    raise _core.ConfigError(
        f"config must be a YAML file path or a dict, got a {type(config).__name__}")
