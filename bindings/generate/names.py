"""Names every emitter derives from C names the same way."""
import re


def camel(c_name):
    """nl_link_settings -> LinkSettings; NL_AGENT_IDLE -> AgentIdle."""
    return "".join(part.capitalize() for part in re.sub(r"^(nl|NL)_", "", c_name).split("_"))


def enum_prefix(names):
    """The prefix a kind's constants share, up to an underscore: the part its member names drop
    (NL_AGENT_IDLE, NL_AGENT_WALKING -> NL_AGENT_; one constant NL_SEGMENT_WALK -> NL_SEGMENT_)."""
    if len(names) == 1:
        return names[0][:names[0].rfind("_") + 1]
    prefix = names[0]
    for n in names[1:]:
        while not n.startswith(prefix):
            prefix = prefix[:-1]
    return prefix[:prefix.rfind("_") + 1]


def is_id(struct):
    """An id (nl_mesh_id, nl_path_ticket...): a struct of exactly `index1` and `generation`."""
    return [f["name"] for f in struct["fields"]] == ["index1", "generation"]


def ordered_items(model):
    """Callbacks and structs in header order (a struct's by-value fields and a callback's types are
    declared before it): [("callback" | "struct", item)]."""
    items = [("callback", c) for c in model["callbacks"]] + [("struct", s) for s in model["structs"]]
    return sorted(items, key=lambda item: (model["headers"].index(item[1]["header"]), item[1]["order"]))
