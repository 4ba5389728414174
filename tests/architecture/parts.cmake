# A made-up layering for the tests of cmake/check_architecture.cmake: low at the bottom, left
# and right side by side on it, high on both.
set(ANCFNET_PARTS low left right high)
set(ANCFNET_PART_low_DEPENDS)
set(ANCFNET_PART_left_DEPENDS low)
set(ANCFNET_PART_right_DEPENDS low)
set(ANCFNET_PART_high_DEPENDS left right)
