// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FirstError.h
/// The collective agreement of Communicator::agree without its "rank R of N: "
/// prefix, for errors whose message already says where they are (a file's
/// line: sltk/cloud/TextCloudFile.h), so that every rank count gives the
/// one-rank message.

#include "sltk/core/Status.h"
#include "sltk/exec/Communicator.h"

namespace sltk
{

/// Collective. Ok on every rank when `local` is ok on every rank, otherwise
/// the status of the lowest failing rank (code and message as that rank
/// wrote them) on every rank; `root` (optional) receives that rank, or
/// comm.size() when all are ok.
Status agreeOnFirstError(const Communicator& comm, const Status& local, int* root = nullptr);

} // namespace sltk
