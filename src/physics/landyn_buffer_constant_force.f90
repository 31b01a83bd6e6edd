!> The buffer law 'constant_force' (&primary_strut / &secondary_strut buffer_law): an ideal crush
!! absorber at one constant force over the whole stroke, the honeycomb's stroke-weighted mean
!! force (the same energy absorbed over the same stroke): on the primary the mean of the stages,
!! rigid in extension; on a secondary the mean of its two levels, in both directions. History and
!! end-of-stroke stops as the honeycomb's (eqs. 21-22).
module landyn_buffer_constant_force
  use landyn_kinds, only: wp
  use landyn_buffer, only: buffer_law_t, rigid_force, history_tol
  use landyn_buffer_build, only: buffer_build_t
  implicit none
  private

  public :: constant_force_t, build

  !> One crush force in both directions up to the capacities, then a stiff stop.
  type, extends(buffer_law_t) :: constant_force_t
    real(wp) :: f = 0.0_wp          !! crush force [N]
    real(wp) :: cap_pos = 0.0_wp    !! stroke toward +s [m]
    real(wp) :: cap_neg = 0.0_wp    !! stroke toward -s [m] (0: rigid at s = 0)
    real(wp) :: k_stop = 1.0e9_wp   !! stop stiffness [N/m]
    real(wp) :: c_stop = 1.0e5_wp   !! stop damping [N s/m]
  contains
    procedure :: resistance => cf_resistance  !! f at the crush fronts, stops beyond the capacities [N]
    procedure :: capacity => cf_capacity      !! cap_pos, cap_neg [m]
    procedure :: segment => cf_segment        !! 0 within the stroke, +1 / -1 on a stop [-]
  end type constant_force_t

contains

  !> The registry's builder of 'constant_force' (landyn_buffer_laws).
  subroutine build(b)
    type(buffer_build_t), intent(inout) :: b   !! the build
    integer :: n
    if (b%check_only) return
    if (b%primary) then
      n = b%pri%n_stages
      allocate (b%law, source=constant_force_t(f=(b%pri%stage_force(1)*b%pri%stage_end(1) + &
        sum(b%pri%stage_force(2:n)*(b%pri%stage_end(2:n) - b%pri%stage_end(1:n - 1))))/b%pri%stage_end(n), &
        cap_pos=b%pri%stage_end(n), cap_neg=0.0_wp, k_stop=b%pri%stop_stiffness, c_stop=b%pri%stop_damping))
    else
      allocate (b%law, source=constant_force_t(f=(b%sec%force_lengthening*b%sec%stroke_lengthening + &
        b%sec%force_shortening*b%sec%stroke_shortening)/(b%sec%stroke_lengthening + b%sec%stroke_shortening), &
        cap_pos=b%sec%stroke_lengthening, cap_neg=b%sec%stroke_shortening, k_stop=b%sec%stop_stiffness, &
        c_stop=b%sec%stop_damping))
    end if
  end subroutine build

  !> f at the crush front of each direction (with the stop beyond a capacity), 0 inside the crushed
  !! range; rigid toward -s at s <= 0 without stroke toward -s.
  pure subroutine cf_resistance(self, s, s_dot, s_hismin, s_hismax, f_pos, f_neg)
    class(constant_force_t), intent(in) :: self  !! the buffer law
    real(wp), intent(in) :: s          !! stroke [m]
    real(wp), intent(in) :: s_dot      !! stroke rate [m/s]
    real(wp), intent(in) :: s_hismin   !! most negative stroke reached so far [m]
    real(wp), intent(in) :: s_hismax   !! most positive stroke reached so far [m]
    real(wp), intent(out) :: f_pos     !! bound against motion toward +s [N]
    real(wp), intent(out) :: f_neg     !! bound against motion toward -s [N]
    f_pos = 0.0_wp
    if (s >= s_hismax - history_tol) then
      f_pos = self%f
      if (s > self%cap_pos) f_pos = self%f + self%k_stop*(s - self%cap_pos) + self%c_stop*max(s_dot, 0.0_wp)
    end if
    f_neg = 0.0_wp
    if (self%cap_neg <= 0.0_wp) then
      if (s <= max(0.0_wp, s_hismin) + history_tol) f_neg = rigid_force
    else if (s <= s_hismin + history_tol) then
      f_neg = self%f
      if (-s > self%cap_neg) f_neg = self%f + self%k_stop*(-s - self%cap_neg) + self%c_stop*max(-s_dot, 0.0_wp)
    end if
  end subroutine cf_resistance

  !> The capacities.
  pure subroutine cf_capacity(self, cap_pos, cap_neg)
    class(constant_force_t), intent(in) :: self  !! the buffer law
    real(wp), intent(out) :: cap_pos   !! stroke toward +s [m]
    real(wp), intent(out) :: cap_neg   !! stroke toward -s [m]
    cap_pos = self%cap_pos
    cap_neg = self%cap_neg
  end subroutine cf_capacity

  !> 0 within the stroke, +1 beyond cap_pos, -1 beyond cap_neg.
  pure integer function cf_segment(self, s) result(seg)
    class(constant_force_t), intent(in) :: self  !! the buffer law
    real(wp), intent(in) :: s          !! stroke [m]
    seg = 0
    if (s > self%cap_pos) seg = 1
    if (self%cap_neg > 0.0_wp .and. -s > self%cap_neg) seg = -1
  end function cf_segment

end module landyn_buffer_constant_force
