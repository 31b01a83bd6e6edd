!> What a buffer-law builder works on (`buffer_build_t`, the build of the buffer-law registry
!! landyn_buffer_laws): the &primary_strut and &secondary_strut input, which strut's law is asked
!! for, and the law built.
!!
!! Every buffer-law module has a builder `build(b)`. With b%check_only (the input validation) it
!! appends the checks that depend on the law, if any, and builds nothing; otherwise it appends the
!! same checks and allocates b%law for the strut b%primary names (the registry discards the law when
!! a check failed). A law for one kind of strut only says so with b%require.
module landyn_buffer_build
  use landyn_config, only: primary_cfg_t, secondary_cfg_t
  use landyn_law_checks, only: law_build_t
  use landyn_buffer, only: buffer_law_t
  implicit none
  private

  public :: buffer_build_t

  !> A build of the buffer-law registry: group 'primary_strut' or 'secondary_strut', variable
  !! 'buffer_law'.
  type, extends(law_build_t) :: buffer_build_t
    logical :: primary = .true.                   !! the primary strut's law (else the secondaries') [-]
    type(primary_cfg_t) :: pri                    !! resolved &primary_strut input
    type(secondary_cfg_t) :: sec                  !! resolved &secondary_strut input
    class(buffer_law_t), allocatable :: law       !! the law built (also when a check failed)
  end type buffer_build_t

end module landyn_buffer_build
