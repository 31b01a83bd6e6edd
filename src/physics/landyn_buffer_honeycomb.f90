!> The buffer law 'honeycomb' (&primary_strut / &secondary_strut buffer_law): the paper's
!! aluminium-honeycomb crush laws of landyn_buffer, on the primary strut the multi-stage law of
!! eq. 21 (primary_honeycomb_t: n_stages, stage_force, stage_end), on a secondary strut the
!! two-direction law of eq. 22 (secondary_honeycomb_t: force_/stroke_lengthening and _shortening),
!! each with its end-of-stroke stop (stop_stiffness, stop_damping). Their ranges are the input
!! registry's and landyn_input_validate's; the law adds no check of its own.
module landyn_buffer_honeycomb
  use landyn_buffer, only: primary_honeycomb_t, secondary_honeycomb_t
  use landyn_buffer_build, only: buffer_build_t
  implicit none
  private

  public :: build

contains

  !> The registry's builder of 'honeycomb' (landyn_buffer_laws).
  subroutine build(b)
    type(buffer_build_t), intent(inout) :: b   !! the build
    if (b%check_only) return
    if (b%primary) then
      allocate (b%law, source=primary_honeycomb_t(n_stages=b%pri%n_stages, stage_force=b%pri%stage_force, &
                stage_end=b%pri%stage_end, k_stop=b%pri%stop_stiffness, c_stop=b%pri%stop_damping))
    else
      allocate (b%law, source=secondary_honeycomb_t(f_lengthening=b%sec%force_lengthening, &
                f_shortening=b%sec%force_shortening, stroke_lengthening=b%sec%stroke_lengthening, &
                stroke_shortening=b%sec%stroke_shortening, k_stop=b%sec%stop_stiffness, c_stop=b%sec%stop_damping))
    end if
  end subroutine build

end module landyn_buffer_honeycomb
