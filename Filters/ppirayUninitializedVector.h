/**
 * @file   ppirayUninitializedVector.h
 * @brief  a std::vector whose resize() leaves new elements uninitialized
 *
 * For arrays that a parallel loop fills entirely right after they are
 * sized: value-initialization would write every byte once on one thread
 * first (and take the first touch of fresh pages there); default
 * initialization of a trivial type writes nothing, so the loop's threads
 * touch their own parts.
 */
#ifndef ppirayUninitializedVector_h
#define ppirayUninitializedVector_h

#include <memory>  // for std::allocator
#include <new>     // for placement new
#include <utility> // for std::forward
#include <vector>  // for std::vector

namespace ppiray
{
/** std::allocator, but construct() without arguments default-initializes. */
template<typename T>
class DefaultInitAllocator : public std::allocator<T>
{
public:
  template<typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  using std::allocator<T>::allocator;

  template<typename U>
  void construct(U* p)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template<typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template<typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;
}

#endif
