// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_MPI_COMMUNICATION_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_MPI_COMMUNICATION_H

// Typed MPI exchanges of trivially copyable records (counts in records, not bytes, so that a
// message may exceed 2 GB), and the collective agreement on errors: a failure on one rank becomes
// the same exception on every rank, never a hang.

#include <CGAL/PR_star_octree/Distributed_mesh_part.h>

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace PR_star_octree {

namespace internal {

/// An MPI datatype of `sizeof(T)` bytes, freed with the object.
template <class T>
class Mpi_record_type {
public:
  Mpi_record_type() {
    static_assert(std::is_trivially_copyable<T>::value, "MPI records must be trivially copyable");
    MPI_Type_contiguous(static_cast<int>(sizeof(T)), MPI_BYTE, &type_);
    MPI_Type_commit(&type_);
  }
  ~Mpi_record_type() { MPI_Type_free(&type_); }
  Mpi_record_type(const Mpi_record_type&) = delete;
  Mpi_record_type& operator=(const Mpi_record_type&) = delete;
  MPI_Datatype get() const { return type_; }

private:
  MPI_Datatype type_;
};

inline int mpi_rank(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}
inline int mpi_size(MPI_Comm comm) {
  int s = 1;
  MPI_Comm_size(comm, &s);
  return s;
}

inline int checked_count(std::size_t n) {
  if (n > static_cast<std::size_t>((std::numeric_limits<int>::max)()))
    throw std::length_error("an MPI message of more than 2^31 records");
  return static_cast<int>(n);
}

/// `all_to_all()` with buffers kept from one call to the next (their capacity), for exchanges
/// repeated in rounds: no allocation, and no page faults, once the largest round has been seen.
template <class T>
class Exchanger {
public:
  explicit Exchanger(int ranks) : send_(std::size_t(ranks)) {}
  /// the records for rank `r` of the next exchange
  std::vector<T>& to(int r) { return send_[std::size_t(r)]; }
  /// Sends what was put in `to()`, and returns the records received, grouped by source rank in
  /// rank order (valid until the next call); `received_counts[i]`: how many came from rank i.
  /// Adds the bytes sent to `*bytes`.
  const std::vector<T>& exchange(MPI_Comm comm, std::vector<std::size_t>* received_counts = nullptr,
                                 std::size_t* bytes = nullptr) {
    const int p = int(send_.size());
    sc_.resize(p);
    rc_.resize(p);
    sd_.resize(p);
    rd_.resize(p);
    for (int i = 0; i < p; ++i) sc_[i] = checked_count(send_[i].size());
    MPI_Alltoall(sc_.data(), 1, MPI_INT, rc_.data(), 1, MPI_INT, comm);
    std::size_t ns = 0, nr = 0;
    for (int i = 0; i < p; ++i) {
      sd_[i] = checked_count(ns);
      rd_[i] = checked_count(nr);
      ns += std::size_t(sc_[i]);
      nr += std::size_t(rc_[i]);
    }
    sbuf_.clear();
    for (auto& s : send_) {
      sbuf_.insert(sbuf_.end(), s.begin(), s.end());
      s.clear();
    }
    rbuf_.resize(nr);
    MPI_Alltoallv(sbuf_.data(), sc_.data(), sd_.data(), type_.get(), rbuf_.data(), rc_.data(), rd_.data(),
                  type_.get(), comm);
    if (received_counts) received_counts->assign(rc_.begin(), rc_.end());
    if (bytes) *bytes += ns * sizeof(T);
    return rbuf_;
  }
  /// the records of the last exchange, moved out
  std::vector<T> take_received() { return std::move(rbuf_); }

private:
  std::vector<std::vector<T>> send_;
  std::vector<T> sbuf_, rbuf_;
  std::vector<int> sc_, rc_, sd_, rd_;
  Mpi_record_type<T> type_;
};

/// Sends `send[i]` (the records for rank i, `send.size()` = the number of ranks) and returns
/// the records received, grouped by source rank in rank order; `received_counts[i]` tells how many
/// came from rank i.  The send buffers are released.
template <class T>
std::vector<T> all_to_all(MPI_Comm comm, std::vector<std::vector<T>>& send,
                          std::vector<std::size_t>* received_counts = nullptr) {
  Exchanger<T> exchanger(int(send.size()));
  for (std::size_t r = 0; r < send.size(); ++r) {
    exchanger.to(int(r)).swap(send[r]);
    std::vector<T>().swap(send[r]);
  }
  exchanger.exchange(comm, received_counts);
  return exchanger.take_received();
}

/// Every rank's `value`, in rank order, on every rank.
template <class T>
std::vector<T> all_gather(MPI_Comm comm, const T& value) {
  std::vector<T> r(mpi_size(comm));
  const Mpi_record_type<T> type;
  MPI_Allgather(&value, 1, type.get(), r.data(), 1, type.get(), comm);
  return r;
}

/// The concatenation of every rank's `values`, in rank order, on every rank.
template <class T>
std::vector<T> all_gather_vectors(MPI_Comm comm, const std::vector<T>& values) {
  const int p = mpi_size(comm);
  const int n = checked_count(values.size());
  std::vector<int> counts(p), displ(p);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::size_t total = 0;
  for (int i = 0; i < p; ++i) {
    displ[i] = checked_count(total);
    total += std::size_t(counts[i]);
  }
  std::vector<T> r(total);
  const Mpi_record_type<T> type;
  MPI_Allgatherv(values.data(), n, type.get(), r.data(), counts.data(), displ.data(), type.get(), comm);
  return r;
}

/// The concatenation of every rank's `values`, in rank order, on rank 0 (empty elsewhere).
template <class T>
std::vector<T> gather_vectors(MPI_Comm comm, const std::vector<T>& values) {
  const int p = mpi_size(comm), me = mpi_rank(comm);
  const int n = checked_count(values.size());
  std::vector<int> counts(p), displ(p);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::size_t total = 0;
  for (int i = 0; i < p; ++i) {
    displ[i] = checked_count(total);
    total += std::size_t(counts[i]);
  }
  std::vector<T> r(me == 0 ? total : 0);
  const Mpi_record_type<T> type;
  MPI_Gatherv(values.data(), n, type.get(), r.data(), counts.data(), displ.data(), type.get(), 0, comm);
  return r;
}

/// The sum of `value` over the ranks, added in rank order (the same bits on every rank for floating
/// point values, whatever the MPI implementation's reduction tree).
template <class T>
T sum_in_rank_order(MPI_Comm comm, const T& value) {
  const std::vector<T> all = all_gather(comm, value);
  T s{};
  for (const T& x : all) s += x;
  return s;
}

/// A failure on any rank raised on every rank: call it at points every rank reaches, with the local
/// error message (empty when this rank is fine).  Throws `Distributed_error` with the first
/// failing rank's message (prefixed by its rank when there are several ranks) on every rank.
inline void agree_on_errors(MPI_Comm comm, const std::string& local_error) {
  const int failed = local_error.empty() ? 0 : 1;
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, comm);
  if (!any) return;
  const int me = mpi_rank(comm), p = mpi_size(comm);
  int first = failed ? me : p;
  int first_failed = p;
  MPI_Allreduce(&first, &first_failed, 1, MPI_INT, MPI_MIN, comm);
  unsigned long long n = me == first_failed ? local_error.size() : 0;
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, first_failed, comm);
  std::string message = me == first_failed ? local_error : std::string(n, ' ');
  MPI_Bcast(&message[0], checked_count(n), MPI_CHAR, first_failed, comm);
  if (p > 1 && message.find("rank ") != 0) message = "rank " + std::to_string(first_failed) + ": " + message;
  throw Distributed_error(message);
}

/// Runs `f()`, then agrees with the other ranks on whether any of them failed (see
/// `agree_on_errors()`): every rank leaves with the same outcome.
template <class F>
void run_collectively(MPI_Comm comm, F&& f) {
  std::string error;
  try {
    f();
  } catch (const std::exception& e) {
    error = e.what();
    if (error.empty()) error = "unknown error";
  }
  agree_on_errors(comm, error);
}

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_MPI_COMMUNICATION_H
