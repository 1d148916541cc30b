"""The test's loopback DDS domain, 1-200: the first from 1 + (pid + offset) % 200 on that no other
test process holds, as test_domain() in tests/service/service_process.cc claims its own (an flock
on the same lock files, held while this process lives)."""
import fcntl
import os
import tempfile

_claims = {}


def claim(offset=0):
    """Claims a domain for this process (the same one on every call with the same offset)."""
    if offset in _claims:
        return _claims[offset][0]
    directory = os.path.join(tempfile.gettempdir(), "gearcoupling-test-domains")
    os.makedirs(directory, exist_ok=True)
    try:
        os.chmod(directory, 0o1777)
    except OSError:
        pass
    first = (os.getpid() + offset) % 200
    for i in range(200):
        domain = 1 + (first + i) % 200
        try:
            lock = open(os.path.join(directory, str(domain)), "a+")
        except OSError:
            continue
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            lock.close()
            continue
        _claims[offset] = (domain, lock)  # the open file is the claim
        return domain
    return 1 + first  # every domain held: the pid's, as before
