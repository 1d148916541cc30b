// The DDS domain each test process claims (service_process.h): two processes starting from the
// same domain never share it, and a claim outlives its process in the children it started.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "tests/service/service_process.h"

namespace gc::test {
namespace {

/// The domain a forked child claims when it starts from `first`; -1 when the child failed.
int claimed_in_a_child(int first) {
  const pid_t child = fork();
  if (child == 0) _exit(claim_test_domain_from(first));
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

TEST(TestDomain, AProcessStartingFromAClaimedDomainTakesTheNextFreeOne) {
  const int mine = test_domain();
  ASSERT_GE(mine, 1);
  ASSERT_LE(mine, 200);
  EXPECT_EQ(test_domain(), mine);  // one claim per process
  const int theirs = claimed_in_a_child(mine - 1);  // starts at mine
  EXPECT_NE(theirs, mine);
  EXPECT_GE(theirs, 1);
  EXPECT_LE(theirs, 200);
}

TEST(TestDomain, AClaimIsHeldByTheChildrenItStartedAfterItsProcessEnds) {
  // A child claims a domain, starts a grandchild that inherits the claim and sleeps, and exits.
  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  const pid_t child = fork();
  if (child == 0) {
    const int domain = claim_test_domain_from(static_cast<int>(getpid() % 200));
    if (write(pipe_fds[1], &domain, sizeof domain) != sizeof domain) _exit(1);
    if (fork() == 0) {
      execl("/bin/sleep", "sleep", "3", static_cast<char*>(nullptr));  // the orphan, holding it
      _exit(1);
    }
    _exit(0);
  }
  close(pipe_fds[1]);
  int orphans = -1;
  ASSERT_EQ(read(pipe_fds[0], &orphans, sizeof orphans), static_cast<ssize_t>(sizeof orphans));
  close(pipe_fds[0]);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_NE(claimed_in_a_child(orphans - 1), orphans);  // its parent has exited: still held
}

}  // namespace
}  // namespace gc::test
