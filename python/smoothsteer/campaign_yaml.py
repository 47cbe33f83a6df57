"""Reading a campaign spec (docs/campaigns.md) as the scenario loader reads a scenario: every
key checked, unknown and repeated keys rejected, each error naming the file, the key and its
line, and numbers written as in a scenario file (`0.5`, `-1e-3`; no `inf` or `nan`)."""
import math
import re

import yaml

from . import ConfigError

# A scenario file's numbers (docs/scenarios.md): decimal, magnitude at most 1e9.
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
MAX_MAGNITUDE = 1e9


class CampaignSpecError(ConfigError):
    """A campaign spec that cannot run; the message names the file, the key and the rule."""


class Node:
    """A value of the spec with its file, its key path ('variables.speed.initial_mps.low')
    and its line, so that every check can name where the value came from."""

    def __init__(self, file, key, value, line, lines):
        self.file, self.key, self.value, self.line, self._lines = file, key, value, line, lines

    def fail(self, rule):
        if not self.key:
            raise CampaignSpecError(f"{self.file}: {rule}")
        where = f" (line {self.line})" if self.line else ""
        raise CampaignSpecError(f"{self.file}: key '{self.key}'{where}: {rule}")

    def child(self, name):
        key = f"{self.key}.{name}" if self.key else str(name)
        value = self.value[name] if isinstance(self.value, dict) else self.value[int(name)]
        return Node(self.file, key, value, self._lines.get(key, self.line), self._lines)

    def mapping(self, known, required=()):
        """The keys of a mapping, checked against `known` and `required`, in file order."""
        if not isinstance(self.value, dict):
            self.fail(f"must be a mapping with keys {', '.join(known)}")
        for name in self.value:
            if known is not None and name not in known:
                self.child(name).fail(f"unknown key (known keys here: {', '.join(sorted(known))})")
        for name in required:
            if name not in self.value:
                self.fail(f"missing key '{name}'")
        return list(self.value)

    def items(self):
        if not isinstance(self.value, list):
            self.fail("must be a list")
        return [self.child(index) for index in range(len(self.value))]

    def text(self):
        if not isinstance(self.value, str) or not self.value:
            self.fail(f"must be a non-empty string, got {self.value!r}")
        return self.value

    def number(self, low=-MAX_MAGNITUDE, high=MAX_MAGNITUDE, rule=None):
        value = self.value
        if isinstance(value, str) and _NUMBER.match(value.strip()):
            value = float(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(f"must be a number, got {self.value!r}")
        if not math.isfinite(value) or abs(value) > MAX_MAGNITUDE:
            self.fail(f"value {self.value!r} must be finite with magnitude at most 1e9")
        if not low <= value <= high:
            self.fail(f"value {value!r} out of range: {rule or f'must be in [{low}, {high}]'}")
        return float(value)

    def integer(self, low, high):
        value = self.value
        if isinstance(value, bool) or not isinstance(value, int):
            self.fail(f"must be an integer, got {value!r}")
        if not low <= value <= high:
            self.fail(f"value {value} out of range: must be in [{low}, {high}]")
        return value


def _walk(node, key, lines, file, visiting):
    """Records the line of every key and rejects repeated keys and self-containing aliases."""
    if id(node) in visiting:
        raise CampaignSpecError(f"{file}: key '{key}' (line {node.start_mark.line + 1}): an "
                                "alias refers to a node that contains it")
    visiting.add(id(node))
    if isinstance(node, yaml.MappingNode):
        seen = set()
        for key_node, value_node in node.value:
            name = key_node.value
            path = f"{key}.{name}" if key else name
            if name in seen:
                raise CampaignSpecError(f"{file}: key '{path}' (line "
                                        f"{key_node.start_mark.line + 1}): repeated key")
            seen.add(name)
            lines[path] = key_node.start_mark.line + 1
            _walk(value_node, path, lines, file, visiting)
    elif isinstance(node, yaml.SequenceNode):
        for index, item in enumerate(node.value):
            path = f"{key}.{index}"
            lines[path] = item.start_mark.line + 1
            _walk(item, path, lines, file, visiting)
    visiting.discard(id(node))


def read(file):
    """The spec file as a Node over its parsed content."""
    try:
        with open(file, encoding="utf-8") as handle:
            text = handle.read(1 << 20)
    except (OSError, UnicodeDecodeError) as error:
        raise CampaignSpecError(f"{file}: cannot read the campaign spec: {error}") from None
    loader = yaml.SafeLoader(text)
    try:
        root = loader.get_single_node()
        lines = {}
        if root is not None:
            _walk(root, "", lines, file, set())
        value = loader.construct_document(root) if root is not None else None
    except yaml.YAMLError as error:
        raise CampaignSpecError(f"{file}: not valid YAML: {error}") from None
    finally:
        loader.dispose()
    return Node(file, "", value, 0, lines)
