"""The scene a participant is given in Init, read as the coupler reads it."""

import re
from dataclasses import dataclass
from pathlib import Path

import yaml


class _Loader(yaml.SafeLoader):
    """YAML as yaml-cpp reads it where scenes differ: PyYAML follows YAML 1.1, in which a
    number without a dot (1e-3) is a string; the coupler reads a number."""


_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?[0-9][0-9_]*(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"))


@dataclass
class Scene:
    file: Path  # as given to cosim run; relative paths in the scene are relative to its folder
    text: str   # the YAML exactly as the coupler read it
    data: dict  # the YAML, parsed

    @staticmethod
    def parse(file, text):
        return Scene(Path(file), text, yaml.load(text, Loader=_Loader) or {})

    @property
    def bodies(self):
        """The bodies' mappings, in scene order: the order of Poses and Forces rows."""
        return self.data.get("bodies") or []

    def section(self, name):
        """participants.<name>, this participant's own section."""
        return self.data["participants"][name]

    def options(self, name):
        return self.section(name).get("options") or {}
