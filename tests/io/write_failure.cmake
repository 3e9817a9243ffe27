# A write that fails stops the run with a message and a non-zero exit. The output directory OUT is
# prepared with LINK (a file name the run writes) as a symbolic link to /dev/full, on which every
# write fails with "No space left on device" (a full disk, also for root, unlike a read-only
# directory). Then expect_error.cmake runs COMMAND and checks the status and the message.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(CREATE_LINK /dev/full ${OUT}/${LINK} SYMBOLIC)
include(${CMAKE_CURRENT_LIST_DIR}/expect_error.cmake)
