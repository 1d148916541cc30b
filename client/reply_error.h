// An error reply back into the exception the core would have thrown in process, so callers
// (the CLI) treat remote and in-process errors alike.
#pragma once

namespace gc::client {

/// Throws, for `status` (gearcoupling_ReplyStatus):
/// - STATUS_INVALID_INPUT: gc::InvalidInput with the same field() and the same what() as the
///   core's (the message is the core's what(), parsed back into its parts);
/// - STATUS_NOT_CONVERGED: gc::NotConverged(message); STATUS_MODEL_ERROR: gc::ModelError;
/// - otherwise, or when the message is not in the core's form: protocol::ServiceError.
[[noreturn]] void throw_reply_error(int status, const char* field, const char* message);

}  // namespace gc::client
