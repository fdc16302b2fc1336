// Roth interval lists ("tLists", TList.h of the listing, lines 2500-2510).
//
// The listing keeps a ray/object classification as a malloc'd linked list of
//   typedef struct A { double val; int primNum, surfType; Vector norm; struct A *next; } TList;
// built two nodes at a time by AddToTList (tList module, 7888-7912): the entry
// node (val = tIn, surfType Out, norm = nIn) and the exit node (val = tOut,
// surfType In, norm = nOut). Every operation of the tList module (Add, Kill,
// Copy, TListDel) moves, drops or overwrites whole nodes, so a list always has
// an even number of nodes.
//
// The port stores the same nodes contiguously: entry nodes at even positions,
// exit nodes at odd positions, in list order, in a small-buffer vector (no heap
// allocation up to kInlineNodes nodes). There is no global state: the
// listing's global `tListPos` (Global module 3800-3820, E14) is local to each
// CSG operator call (see csg_1991.cpp).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "src/math/vec.h"

namespace prime {

// Define.h (2357-2358): surface classification of a tList node.
inline constexpr int kSurfOut = 0;  // `Out`: the entry node of a pair (AddToTList)
inline constexpr int kSurfIn = 1;   // `In`: the exit node of a pair

// One tList node without its `next` pointer: exactly the four fields that the
// listing's Copy() transfers (val, primNum, surfType, norm).
struct TNode {
  double t = 0.0;           // val: ray parameter (world = primitive space, E55)
  int prim = 0;             // primNum
  int surfType = kSurfOut;  // Out (0) or In (1)
  Vec3 norm{};              // normal as the primitive routine returned it (local frame)

  friend bool operator==(const TNode&, const TNode&) = default;
};

// Contiguous vector with N elements of inline storage; grows onto the heap
// beyond that. Minimal by design (what TList and the CSG walk need).
template <class T, std::size_t N>
class SmallVec {
  static_assert(N > 0);
  static_assert(std::is_nothrow_move_constructible_v<T>);
  static_assert(std::is_nothrow_destructible_v<T>);

 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  // User-provided, so value-initialisation (`TList{}`) does not zero the
  // inline buffer first: a CSG walk creates one per tree entry.
  SmallVec() noexcept {}  // NOLINT(modernize-use-equals-default)
  SmallVec(std::initializer_list<T> init) {
    reserve(init.size());
    std::uninitialized_copy(init.begin(), init.end(), data_);
    size_ = init.size();
  }
  SmallVec(const SmallVec& other) {
    reserve(other.size_);
    std::uninitialized_copy(other.begin(), other.end(), data_);
    size_ = other.size_;
  }
  SmallVec(SmallVec&& other) noexcept { takeFrom(other); }
  SmallVec& operator=(const SmallVec& other) {
    if (this != &other) {
      clear();
      reserve(other.size_);
      std::uninitialized_copy(other.begin(), other.end(), data_);
      size_ = other.size_;
    }
    return *this;
  }
  SmallVec& operator=(SmallVec&& other) noexcept {
    if (this != &other) {
      release();
      takeFrom(other);
    }
    return *this;
  }
  ~SmallVec() { release(); }

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] std::size_t capacity() const noexcept { return cap_; }
  [[nodiscard]] bool isInline() const noexcept { return data_ == inlineData(); }

  T* data() noexcept { return data_; }
  const T* data() const noexcept { return data_; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }
  T& back() noexcept { return data_[size_ - 1]; }
  const T& back() const noexcept { return data_[size_ - 1]; }
  iterator begin() noexcept { return data_; }
  iterator end() noexcept { return data_ + size_; }
  const_iterator begin() const noexcept { return data_; }
  const_iterator end() const noexcept { return data_ + size_; }

  void reserve(std::size_t n) {
    if (n <= cap_) return;
    std::size_t newCap = cap_ * 2;
    if (newCap < n) newCap = n;
    T* fresh = std::allocator<T>().allocate(newCap);
    std::uninitialized_move(data_, data_ + size_, fresh);
    std::destroy(data_, data_ + size_);
    if (!isInline()) std::allocator<T>().deallocate(data_, cap_);
    data_ = fresh;
    cap_ = newCap;
  }
  template <class... Args>
  T& emplace_back(Args&&... args) {
    if (size_ == cap_) reserve(size_ + 1);
    T* p = std::construct_at(data_ + size_, std::forward<Args>(args)...);
    ++size_;
    return *p;
  }
  void push_back(const T& v) { emplace_back(v); }
  void push_back(T&& v) { emplace_back(std::move(v)); }
  void pop_back() noexcept {
    --size_;
    std::destroy_at(data_ + size_);
  }
  void clear() noexcept {
    std::destroy(data_, data_ + size_);
    size_ = 0;
  }

 private:
  T* inlineData() noexcept { return reinterpret_cast<T*>(inline_); }
  const T* inlineData() const noexcept { return reinterpret_cast<const T*>(inline_); }

  // Frees everything and returns to the empty inline state.
  void release() noexcept {
    clear();
    if (!isInline()) std::allocator<T>().deallocate(data_, cap_);
    data_ = inlineData();
    cap_ = N;
  }
  // Precondition: *this is empty and inline. Leaves `other` empty and inline.
  void takeFrom(SmallVec& other) noexcept {
    if (other.isInline()) {
      std::uninitialized_move(other.begin(), other.end(), data_);
      size_ = other.size_;
      other.clear();
    } else {
      data_ = other.data_;
      size_ = other.size_;
      cap_ = other.cap_;
      other.data_ = other.inlineData();
      other.size_ = 0;
      other.cap_ = N;
    }
  }

  T* data_ = inlineData();
  std::size_t size_ = 0;
  std::size_t cap_ = N;
  alignas(T) unsigned char inline_[N * sizeof(T)];
};

// A tList: pairs of nodes, entry at 2k, exit at 2k+1, in list order. The
// 1991 operators leave lists unsorted and can create inverted or degenerate
// pairs (K30, Q3); the type does not enforce any order. Its one invariant is
// the listing's: an even number of nodes.
class TList {
 public:
  static constexpr std::size_t kInlineNodes = 8;  // 4 pairs without heap use

  TList() noexcept {}  // NOLINT(modernize-use-equals-default): see SmallVec()
  TList(std::initializer_list<TNode> nodes) : nodes_(nodes) {}

  // AddToTList (7888-7912, E56) onto an empty list: [tIn (Out, nIn), tOut (In, nOut)].
  static TList pair(double tIn, double tOut, const Vec3& nIn, const Vec3& nOut, int prim) {
    TList l;
    l.addPair(tIn, tOut, nIn, nOut, prim);
    return l;
  }

  // Appends one pair as AddToTList builds it.
  void addPair(double tIn, double tOut, const Vec3& nIn, const Vec3& nOut, int prim) {
    nodes_.push_back(TNode{tIn, prim, kSurfOut, nIn});
    nodes_.push_back(TNode{tOut, prim, kSurfIn, nOut});
  }
  // Appends two nodes as they are (an Add() of the tList module).
  void pushPair(const TNode& entry, const TNode& exit) {
    nodes_.push_back(entry);
    nodes_.push_back(exit);
  }
  void push_back(const TNode& n) { nodes_.push_back(n); }
  void reserve(std::size_t n) { nodes_.reserve(n); }
  void clear() noexcept { nodes_.clear(); }  // TListDel (7916-7930)

  [[nodiscard]] std::size_t size() const noexcept { return nodes_.size(); }
  [[nodiscard]] bool empty() const noexcept { return nodes_.empty(); }  // *tList == NULL
  [[nodiscard]] std::size_t pairCount() const noexcept { return nodes_.size() / 2; }
  // True when the node count is even (always, for lists the listing can build).
  [[nodiscard]] bool wellFormed() const noexcept { return nodes_.size() % 2 == 0; }

  TNode& operator[](std::size_t i) noexcept { return nodes_[i]; }
  const TNode& operator[](std::size_t i) const noexcept { return nodes_[i]; }
  const TNode& entry(std::size_t pairIndex) const noexcept { return nodes_[2 * pairIndex]; }
  const TNode& exit(std::size_t pairIndex) const noexcept { return nodes_[2 * pairIndex + 1]; }
  // The node IntersectObj reports (6365-6372): the FIRST node, not the nearest (K30).
  const TNode& front() const noexcept { return nodes_[0]; }

  TNode* begin() noexcept { return nodes_.begin(); }
  TNode* end() noexcept { return nodes_.end(); }
  const TNode* begin() const noexcept { return nodes_.begin(); }
  const TNode* end() const noexcept { return nodes_.end(); }

  [[nodiscard]] bool usesHeap() const noexcept { return !nodes_.isInline(); }

  friend bool operator==(const TList& a, const TList& b) noexcept {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!(a[i] == b[i])) return false;
    return true;
  }

 private:
  SmallVec<TNode, kInlineNodes> nodes_;
};

// Errors of the CSG code. The listing reports all of them through Error(),
// which prints and exits (K44); the port throws and lets the caller decide.
class CsgError : public std::runtime_error {
 public:
  enum class Kind {
    kKillEmptyList,  // E57: Kill() of an empty list (Difference's double Kill, Q3)
    kAddEmptyList,   // Add() of an empty list: a NULL dereference (unreachable from the listing)
    kOddList,        // a list with an odd node count (cannot be built by the listing)
    kBadOpcode,      // CSG(): "switch case fell to default. Module Roth. Program CSG"
    kBadEntryIndex,  // ReadObj(): "Invalid read attempt" (child index outside the tree)
    kCycle,          // the tree is not a tree: a path revisits an entry
    kTooManyVisits,  // the walk exceeded its visit budget (nested shared subtrees)
  };
  CsgError(Kind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  [[nodiscard]] Kind kind() const noexcept { return kind_; }

 private:
  Kind kind_;
};

// Text forms for diagnostics and test failure messages.
std::ostream& operator<<(std::ostream& os, const TNode& n);
std::ostream& operator<<(std::ostream& os, const TList& l);

}  // namespace prime
