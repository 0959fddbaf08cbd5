"""One function per element type of the catalogue, built from its specs.

``hbtrack.elements.tip_contact(["n1_r", "n1_t", "n1_z"], stiffness=..., ...)`` returns the
``[[elements]]`` table as a dict, the form ``case_from_arrays(elements=[...])`` takes. The
functions, their signatures and their numpydoc docstrings come from hbtrack's element catalogue
(the C++ list the case reader checks against), so they name exactly the keys the reader accepts;
the values are checked when the case is read, with the case reader's messages.
"""
import inspect

BINDING = "float, str or dict"  # a number, a parameter name, or {parameter, scale, offset}
KEYWORD = inspect.Parameter.KEYWORD_ONLY


def sentence(text):
    """The catalogue's one-line doc with a capital first letter."""
    return text[:1].upper() + text[1:]


def property_variants(info):
    """{property: [(choices, spec), ...]}: the variants of a type that have each property."""
    found = {}
    for variant in info["variants"]:
        for name, spec in variant["properties"].items():
            found.setdefault(name, []).append((variant["choices"], spec))
    return found


def condition(group, all_choices):
    """'law="dlft"': the choices every variant of `group` shares and the others may not."""
    shared = {k: v for k, v in group[0].items()
              if all(c[k] == v for c in group) and len({c[k] for c in all_choices}) > 1}
    return " and ".join(f'{k}="{v}"' for k, v in shared.items())


def property_doc(name, found, info):
    """The numpydoc entry of a property, and whether every variant requires it."""
    all_choices = [v["choices"] for v in info["variants"]]
    unit, doc = found[0][1]["unit"], found[0][1]["doc"]
    lines = [f"{sentence(doc)} [{unit}]."]
    everywhere = len(found) == len(all_choices)
    if not everywhere:
        lines.append(f"Only with {condition([c for c, _ in found], all_choices)}.")
    by_range = {}
    for choices, spec in found:
        by_range.setdefault(spec["range"], []).append(choices)
    for rule, group in by_range.items():
        if rule:
            when = f" with {condition(group, all_choices)}" if len(by_range) > 1 else ""
            lines.append(f"Must be {rule}{when}.")
    defaults = {spec["default"] for _, spec in found}
    required = defaults == {None} and everywhere
    if defaults == {None}:
        lines.append("Required." if everywhere else "Required there.")
    else:
        lines.append(f"Default {next(d for d in defaults if d is not None):g}.")
    return lines, required


def key_doc(name, key):
    """The numpydoc type and entry of a key that decides how the element is built."""
    if key["kind"] == "choice":
        kind = "{" + ", ".join(f'"{v}"' for v in key["values"]) + "}"
    elif key["kind"] == "integer":
        kind = "int"
    else:
        kind = "sequence of sequence"
    lines = [sentence(key["doc"]) + "."]
    if "range" in key:
        lines.append(f"Integers in [{key['range'][0]}, {key['range'][1]}].")
    lines.append("Required." if key["default"] is None else f"Default {key['default']!r}.")
    return kind, lines


def dofs_doc(info):
    if info["weighted"] and info.get("directions", 1) == 2:
        return ("The slider's plane is u = W x of these dofs (two [x, y]: grounded, four "
                "[x_a, y_a, x_b, y_b]: between two nodes, other counts: give `weights`).")
    if info["weighted"]:
        return ("The element acts along d = w.x of these dofs (one: grounded, two: between them, "
                "more: give `weights`).")
    if info["dofs"]:
        return f"Exactly {len(info['dofs'])} dofs: " + ", ".join(info["dofs"]) + "."
    return "Any number k of dofs."


def make_helper(type_name, info):
    """The function that writes one element of `type_name`, with its signature and docstring."""
    parameters = [inspect.Parameter("dofs", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    docs = ["dofs : sequence of str", "    " + dofs_doc(info)]
    optional = []
    for name, key in info["keys"].items():
        kind, lines = key_doc(name, key)
        entry = (inspect.Parameter(name, KEYWORD) if key["default"] is None
                 else inspect.Parameter(name, KEYWORD, default=None))
        (parameters if key["default"] is None else optional).append(entry)
        docs += [f"{name} : {kind}" + ("" if key["default"] is None else ", optional")] + ["    " + x for x in lines]
    for name, found in property_variants(info).items():
        lines, required = property_doc(name, found, info)
        (parameters if required else optional).append(
            inspect.Parameter(name, KEYWORD) if required else inspect.Parameter(name, KEYWORD, default=None))
        docs += [f"{name} : {BINDING}" + ("" if required else ", optional")] + ["    " + x for x in lines]
    if info["weighted"]:
        optional.append(inspect.Parameter("weights", KEYWORD, default=None))
        if info.get("directions", 1) == 2:
            docs += ["weights : sequence of two sequences of float, optional",
                     "    The rows of W in u = W x, one per direction of the plane; default the identity on",
                     "    two dofs, [[1, 0, -1, 0], [0, 1, 0, -1]] on four."]
        else:
            docs += ["weights : sequence of float, optional", "    w of d = w.x; default [1] on one dof, [1, -1] on two."]
    optional.append(inspect.Parameter("lanczos", KEYWORD, default=None))
    docs += ["lanczos : float, optional", "    Lanczos sigma exponent p in [0, 10] for the force harmonics; default 0 (off)."]
    signature = inspect.Signature(parameters + optional)
    names = [p.name for p in signature.parameters.values()]

    def helper(*args, **kwargs):
        bound = signature.bind(*args, **kwargs)  # TypeError naming a missing or unknown argument
        table = {"type": type_name, "dofs": [bound.arguments["dofs"]] if isinstance(bound.arguments["dofs"], str)
                 else list(bound.arguments["dofs"])}
        for name in names[1:]:
            value = bound.arguments.get(name)
            if value is not None:
                table[name] = value
        return table

    helper.__name__ = helper.__qualname__ = type_name
    helper.__module__ = "hbtrack.elements"  # where users find it (and the API docs test checks it)
    helper.__signature__ = signature
    helper.__doc__ = "\n".join([
        f"Element ``{type_name}``: {info['summary']}.", "",
        "Properties are a number, the name of a case parameter, or {parameter, scale, offset};",
        "units are the model's (F force, L length, s time, 1 none). Omitted optional arguments",
        "take the case reader's defaults.", "",
        "Parameters", "----------", *docs, "",
        "Returns", "-------", "dict",
        "    The ``[[elements]]`` table, as ``case_from_arrays(elements=[...])`` takes it.", "",
        "Examples", "--------",
        f">>> hbtrack.elements.{type_name}(" + ", ".join(
            [repr(["x", "y", "z"][:max(1, len(info["dofs"]), info.get("directions", 1))])] + [f"{p.name}=..." for p in parameters[1:]]) + ")",
    ])
    return helper


def element_helpers(types):
    """{type: helper} for every type of `types` (hbtrack.element_types())."""
    return {name: make_helper(name, info) for name, info in types.items()}
