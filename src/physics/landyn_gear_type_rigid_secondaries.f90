!> The gear type 'rigid_secondaries' (&gears gear_type): the tripod with rigid secondary struts,
!! links that never crush (both bounds rigid_force), so the primary strut alone absorbs the
!! landing. Everything else is the tripod's, from the same input (tripod_parts).
module landyn_gear_type_rigid_secondaries
  use landyn_kinds, only: msg_len
  use landyn_buffer, only: secondary_honeycomb_t, rigid_force
  use landyn_tripod_gear, only: tripod_gear_t, tripod_init
  use landyn_gear_build, only: gear_build_t
  use landyn_gear_type_tripod, only: tripod_parts, tripod_parts_t
  implicit none
  private

  public :: rigid_secondaries_gear_t, build

  !> A tripod whose secondaries are rigid links.
  type, extends(tripod_gear_t) :: rigid_secondaries_gear_t
  end type rigid_secondaries_gear_t

contains

  !> The registry's builder of 'rigid_secondaries' (landyn_gear_types): gear b%i of the input.
  subroutine build(b)
    type(gear_build_t), intent(inout) :: b   !! the build
    type(tripod_parts_t) :: p
    type(rigid_secondaries_gear_t) :: gear
    logical :: ok
    integer :: stat
    character(len=msg_len) :: m2
    if (b%check_only) return
    call tripod_parts(b, p, ok)
    if (.not. ok) return
    deallocate (p%secondary)
    allocate (p%secondary, source=secondary_honeycomb_t(f_lengthening=rigid_force, f_shortening=rigid_force))
    call tripod_init(gear%tripod_gear_t, p%geom, p%rot, p%sm, p%primary, p%secondary, stat, m2, p%tube)
    if (stat /= 0) then; call b%errors%add(trim(m2)); return; end if
    allocate (b%gear, source=gear)
  end subroutine build

end module landyn_gear_type_rigid_secondaries
