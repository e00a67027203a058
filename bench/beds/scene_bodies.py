"""The scene's body entries of a run file, one per body."""


def bodies_of(scene, names):
    """The scene's body entries, one per body of the run file (`names`, scene order): an entry
    with `generate` stands for the bodies its name pattern names in a row (Python's format
    reads the patterns {} and {:03d} as cosim does)."""
    bodies, k = [], 0
    for entry in scene["bodies"]:
        if "generate" not in entry:
            bodies.append(entry)
            k += 1
            continue
        i = 0
        while k < len(names) and names[k] == entry["name"].format(i):
            bodies.append(dict(entry, name=names[k]))
            k, i = k + 1, i + 1
    return bodies
