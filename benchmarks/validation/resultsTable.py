"""One results.csv shared by the validation scripts' runs.

Several invocations of a script may run at once (one per core): each new row
is merged into the file as it is now, under a lock, so that one run does not
overwrite the rows another wrote since it started.
"""
import csv
import fcntl
import os


def merge_row(path, fields, key, row):
    """Write row into the CSV at path, replacing the row with the same key;
    returns all rows, sorted by key"""
    with open(path + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        rows = []
        if os.path.exists(path):
            rows = [r for r in csv.DictReader(open(path)) if key(r) != key(row)]
        rows.append({k: row.get(k, "") for k in fields})
        rows.sort(key=key)
        tmp = path + ".tmp"
        with open(tmp, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields)
            w.writeheader()
            w.writerows(rows)
        os.replace(tmp, path)
        return rows
