"""Reading a campaign spec (docs/campaigns.md) as the scenario loader reads a scenario: every
key checked, unknown and repeated keys rejected, each error naming the file, the key and its
line, and numbers written as in a scenario file (`0.5`, `-1e-3`; no `inf` or `nan`).

The file limits are the C++ loaders' (include/smoothsteer/io/bounded_file.hpp and
config_section.hpp): a regular file of at most 16 MiB, refused whole when larger (never cut);
at most 4 000 000 nodes with every alias counted once per use (a "billion laughs" document
expands to 10^9), counted while composing, so a bomb is refused in time linear in its text;
nesting at most 64 deep, checked on the parser's events before composing. Integers are decimal: PyYAML reads YAML 1.1, where `010` is 8, `0xff`
255, `1_0` 10 and `1:30` 90; a scenario file reads none of them as a number."""
import math
import os
import re
import stat

import yaml

from .. import ConfigError

# A scenario file's numbers (docs/scenarios.md): decimal, magnitude at most 1e9.
_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")
_DECIMAL_INTEGER = re.compile(r"^[+-]?(0|[1-9]\d*)$")
_DECIMAL_FLOAT = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$|^[+-]?\.(inf|Inf|INF)$|"
                            r"^\.(nan|NaN|NAN)$")
MAX_MAGNITUDE = 1e9
# The C++ loaders' limits: io::max_yaml_file_bytes, io::max_yaml_nodes, io::max_yaml_depth.
MAX_SPEC_BYTES = 16 << 20
MAX_NODES = 4_000_000
MAX_DEPTH = 64
_DECIMAL_RULE = ("must be written in decimal digits (no leading zero, 0x, 0o, 0b, '_' or ':' "
                 "as YAML 1.1 allows)")


class CampaignSpecError(ConfigError):
    """A campaign spec that cannot run; the message names the file, the key and the rule."""


class NonDecimal(str):
    """A scalar YAML 1.1 reads as a number but a scenario file does not (`010`, `0xff`, `1_0`):
    kept as its text, so that a number check names it and the scenario loader sees it as
    written."""


def _scalar(loader, node, kind, pattern):
    text = loader.construct_scalar(node)
    if not pattern.match(text):
        return NonDecimal(text)
    return getattr(yaml.constructor.SafeConstructor, kind)(loader, node)


class _Loader(getattr(yaml, "CSafeLoader", yaml.SafeLoader)):  # libyaml's parser when there
    pass


_Loader.add_constructor("tag:yaml.org,2002:int", lambda loader, node: _scalar(
    loader, node, "construct_yaml_int", _DECIMAL_INTEGER))
_Loader.add_constructor("tag:yaml.org,2002:float", lambda loader, node: _scalar(
    loader, node, "construct_yaml_float", _DECIMAL_FLOAT))


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

    def items(self, most=None):
        if not isinstance(self.value, list):
            self.fail("must be a list")
        if most is not None and len(self.value) > most:
            self.fail(f"lists {len(self.value)} items, at most {most} allowed")
        return [self.child(index) for index in range(len(self.value))]

    def text(self):
        if not isinstance(self.value, str) or not self.value:
            self.fail(f"must be a non-empty string, got {self.value!r}")
        return str(self.value)

    def number(self, low=-MAX_MAGNITUDE, high=MAX_MAGNITUDE, rule=None):
        value = self.value
        if isinstance(value, NonDecimal):
            self.fail(f"value {str(value)!r} {_DECIMAL_RULE}")
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
        if isinstance(value, NonDecimal):
            self.fail(f"value {str(value)!r} {_DECIMAL_RULE}")
        if isinstance(value, bool) or not isinstance(value, int):
            self.fail(f"must be an integer, got {value!r}")
        if not low <= value <= high:
            self.fail(f"value {value} out of range: must be in [{low}, {high}]")
        return value


class _Walk:
    """One walk over the composed document. PyYAML resolves an alias to the very node its
    anchor names, so the document is a graph; every distinct node is walked once and its
    expansion (its nodes, each alias once per use) remembered, so that a later use only adds
    its count. Records the line of every key on the first way to it (a key reached only
    through an alias takes the alias's line)."""

    def __init__(self, file):
        self.file, self.lines, self.visited = file, {}, 0
        self.expansion, self.open = {}, []

    def fail(self, key, node, rule):
        raise CampaignSpecError(f"{self.file}: key '{key or '<root>'}' (line "
                                f"{node.start_mark.line + 1}): {rule}")

    def count(self, key, node, nodes, height):
        self.visited += nodes
        if self.visited > MAX_NODES:
            self.fail(key, node, f"the document expands to more than {MAX_NODES} nodes "
                                 "(aliases count once per use); not a campaign spec")
        if len(self.open) + height > MAX_DEPTH:
            self.fail(key, node, f"nested deeper than {MAX_DEPTH} levels")

    def walk(self, node, key):
        if isinstance(node, yaml.ScalarNode):
            self.count(key, node, 1, 0)
            return 1, 0
        if any(node is outer for outer in self.open):
            self.fail(key, node, "an alias refers to a node that contains it")
        if id(node) in self.expansion:
            nodes, height = self.expansion[id(node)]
            self.count(key, node, nodes, height)
            return nodes, height
        self.count(key, node, 1, 1)
        self.open.append(node)
        nodes, height = 1, 1
        if isinstance(node, yaml.MappingNode):
            children, seen = [], set()
            for key_node, value_node in node.value:
                if not isinstance(key_node, yaml.ScalarNode):
                    self.fail(key, key_node, "a key must be a plain string, not a list or a "
                                             "mapping")
                name = key_node.value
                path = f"{key}.{name}" if key else name
                if name in seen:
                    self.fail(path, key_node, "repeated key")
                seen.add(name)
                self.lines.setdefault(path, key_node.start_mark.line + 1)
                children.append((value_node, path))
        else:
            children = [(item, f"{key}.{index}") for index, item in enumerate(node.value)]
            for item, path in children:
                self.lines.setdefault(path, item.start_mark.line + 1)
        for child, path in children:
            child_nodes, child_height = self.walk(child, path)
            nodes += child_nodes
            height = max(height, child_height + 1)
        self.open.pop()
        self.expansion[id(node)] = (nodes, height)
        return nodes, height


def _text(file):
    """The file's text: a regular file only (a FIFO would block), read whole up to the limit."""
    try:
        descriptor = os.open(file, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as error:
        raise CampaignSpecError(f"{file}: cannot read the campaign spec: "
                                f"{error.strerror}") from None
    with os.fdopen(descriptor, "rb") as handle:
        mode = os.fstat(descriptor).st_mode
        if not stat.S_ISREG(mode):
            kind = "a directory" if stat.S_ISDIR(mode) else "not a regular file"
            raise CampaignSpecError(f"{file}: the campaign spec is {kind}")
        chunks, size = [], 0
        while size <= MAX_SPEC_BYTES:  # in pieces: read(n) would reserve n bytes at once
            chunk = handle.read(1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        data = b"".join(chunks)
    if len(data) > MAX_SPEC_BYTES:
        raise CampaignSpecError(f"{file}: the campaign spec is larger than {MAX_SPEC_BYTES} "
                                "bytes (16 MiB, the scenario loader's limit); refused whole")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data[:error.start].count(b"\n") + 1
        raise CampaignSpecError(f"{file}: not valid UTF-8 at line {line}") from None


def _check_depth(file, text):
    """Refuses deep nesting from the parser's events, which come without recursion: the
    composer recurses once per level (libyaml's crashes the process at about 10^5 levels)."""
    depth = 0
    for event in yaml.parse(text, Loader=_Loader):
        if isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            depth += 1
            if depth > MAX_DEPTH:
                raise CampaignSpecError(f"{file}: line {event.start_mark.line + 1}: nested "
                                        f"deeper than {MAX_DEPTH} levels")
        elif isinstance(event, (yaml.SequenceEndEvent, yaml.MappingEndEvent)):
            depth -= 1


def read(file):
    """The spec file as a Node over its parsed content."""
    text = _text(file)
    loader = _Loader(text)
    try:
        _check_depth(file, text)
        root = loader.get_single_node()
        walk = _Walk(file)
        if root is not None:
            walk.walk(root, "")
        value = loader.construct_document(root) if root is not None else None
    except yaml.YAMLError as error:
        raise CampaignSpecError(f"{file}: not valid YAML: {' '.join(str(error).split())}") \
            from None
    finally:
        loader.dispose()
    return Node(file, "", value, 0, walk.lines)
