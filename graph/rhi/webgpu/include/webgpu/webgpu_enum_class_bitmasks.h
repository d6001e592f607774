// webgpu_enum_class_bitmasks.h — bit operators for the flag enums of volgraph's Dawn-style
// C++ API (webgpu_cpp.h): `wgpu::BufferUsage::CopyDst | wgpu::BufferUsage::MapRead`, and
// `if (usage & wgpu::BufferUsage::Storage)`. An enum class opts in by specialising
// wgpu::IsWGPUBitmask. Dawn ships a header of this name; Dawn's own can replace this one.
#ifndef WEBGPU_ENUM_CLASS_BITMASKS_H_
#define WEBGPU_ENUM_CLASS_BITMASKS_H_

#include <type_traits>

namespace wgpu {

template <typename T>
struct IsWGPUBitmask {
  static constexpr bool enable = false;
};

// The result of a bit operation: converts to bool (any bit set) and back to the enum.
template <typename T>
struct BoolConvertible {
  using Integral = std::underlying_type_t<T>;
  // Explicit, as in Dawn's header: only the operators make one.
  explicit constexpr BoolConvertible(Integral bits) : value(bits) {}
  constexpr operator bool() const { return value != 0; }
  constexpr operator T() const { return static_cast<T>(value); }
  Integral value;
};

// Maps a bitmask enum, or the result of an operation on one, to the enum.
template <typename T, typename Enable = void>
struct LowerBitmask {
  static constexpr bool enable = false;
};
template <typename T>
struct LowerBitmask<T, std::enable_if_t<IsWGPUBitmask<T>::enable>> {
  static constexpr bool enable = true;
  using type = T;
  static constexpr T Lower(T t) { return t; }
};
template <typename T>
struct LowerBitmask<BoolConvertible<T>> {
  static constexpr bool enable = true;
  using type = T;
  static constexpr T Lower(BoolConvertible<T> t) { return t; }
};

namespace detail {
template <typename T>
constexpr auto Bits(T value) {
  return static_cast<std::underlying_type_t<typename LowerBitmask<T>::type>>(LowerBitmask<T>::Lower(value));
}
}  // namespace detail

template <typename T1, typename T2, typename = std::enable_if_t<LowerBitmask<T1>::enable && LowerBitmask<T2>::enable>>
constexpr BoolConvertible<typename LowerBitmask<T1>::type> operator|(T1 left, T2 right) {
  return BoolConvertible<typename LowerBitmask<T1>::type>(detail::Bits(left) | detail::Bits(right));
}
template <typename T1, typename T2, typename = std::enable_if_t<LowerBitmask<T1>::enable && LowerBitmask<T2>::enable>>
constexpr BoolConvertible<typename LowerBitmask<T1>::type> operator&(T1 left, T2 right) {
  return BoolConvertible<typename LowerBitmask<T1>::type>(detail::Bits(left) & detail::Bits(right));
}
template <typename T1, typename T2, typename = std::enable_if_t<LowerBitmask<T1>::enable && LowerBitmask<T2>::enable>>
constexpr BoolConvertible<typename LowerBitmask<T1>::type> operator^(T1 left, T2 right) {
  return BoolConvertible<typename LowerBitmask<T1>::type>(detail::Bits(left) ^ detail::Bits(right));
}
template <typename T, typename = std::enable_if_t<LowerBitmask<T>::enable>>
constexpr BoolConvertible<typename LowerBitmask<T>::type> operator~(T value) {
  return BoolConvertible<typename LowerBitmask<T>::type>(static_cast<decltype(detail::Bits(value))>(~detail::Bits(value)));
}
template <typename T, typename T2, typename = std::enable_if_t<IsWGPUBitmask<T>::enable && LowerBitmask<T2>::enable>>
constexpr T& operator|=(T& left, T2 right) {
  return left = left | right;
}
template <typename T, typename T2, typename = std::enable_if_t<IsWGPUBitmask<T>::enable && LowerBitmask<T2>::enable>>
constexpr T& operator&=(T& left, T2 right) {
  return left = left & right;
}
template <typename T, typename T2, typename = std::enable_if_t<IsWGPUBitmask<T>::enable && LowerBitmask<T2>::enable>>
constexpr T& operator^=(T& left, T2 right) {
  return left = left ^ right;
}

// True when at most one bit of a bitmask enum is set (an enum, not an operator's result,
// as in Dawn's header).
template <typename T>
constexpr bool HasZeroOrOneBits(T value) {
  using Integral = std::underlying_type_t<T>;
  return (static_cast<Integral>(value) & (static_cast<Integral>(value) - 1)) == 0;
}

}  // namespace wgpu

#endif  // WEBGPU_ENUM_CLASS_BITMASKS_H_
