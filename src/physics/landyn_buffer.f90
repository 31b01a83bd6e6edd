!> Strut buffer laws: aluminium-honeycomb crush absorbers with history (paper eqs. 21-22).
!!
!! A buffer law does not integrate anything itself: it tells the gear solver how much axial force
!! the strut can transmit before it gives way, in each direction of motion, given the stroke and
!! the crush history. The gear solver (landyn_tripod_gear) enforces the crush logic of eqs. 12-13 with
!! these bounds: a strut at rest stays locked while the force it must carry lies within the bounds
!! (N = F, no driving force); beyond a bound it crushes with N = bound and the excess drives its
!! sliding coordinate; a crushing strut whose sliding speed reaches zero locks again.
!!
!! Stroke convention (Table 3's sense, docs/model_conventions.md): each buffer has a stroke coordinate s
!! whose positive direction is the one Table 3 reports positive: for the primary strut
!! s = L0 - L (shortening), for a secondary strut s = L - L0 (lengthening).
!!
!! History (eqs. 21-22): honeycomb crushes only at a stroke beyond its historical extreme in that
!! direction (s >= s_hismax moving +, s <= s_hismin moving -); crushed honeycomb does not spring
!! back, so between s_hismin and s_hismax the strut slides freely (bound 0 in both directions).
!! Beyond the stroke capacity a stiff stop acts: the bound rises as
!! F_last + k_stop (s - capacity) + c_stop max(s_dot, 0).
module landyn_buffer
  use landyn_kinds, only: wp
  implicit none
  private

  public :: buffer_law_t, primary_honeycomb_t, secondary_honeycomb_t
  public :: rigid_force, history_tol

  real(wp), parameter :: rigid_force = 1.0e30_wp  !! bound of a rigid mechanical stop [N]
  real(wp), parameter :: history_tol = 1.0e-9_wp  !! tolerance on reaching the crush front [m]

  !> Interface of every buffer law.
  type, abstract :: buffer_law_t
  contains
    procedure(resistance_iface), deferred :: resistance  !! force bounds against motion toward +s and -s [N]
    procedure(capacity_iface), deferred :: capacity      !! stroke capacity toward +s and -s [m]
    procedure(segment_iface), deferred :: segment        !! piece of the force-stroke curve at s (for event location) [-]
    procedure :: free_range => history_free_range        !! strokes between which the buffer offers no resistance [m]
    procedure :: crush_levels => initial_crush_levels    !! its constant crush forces, for reports [N]
  end type buffer_law_t

  abstract interface
    !> Largest axial force the buffer can exert against motion toward +s (f_pos) and toward -s (f_neg).
    pure subroutine resistance_iface(self, s, s_dot, s_hismin, s_hismax, f_pos, f_neg)
      import :: buffer_law_t, wp
      class(buffer_law_t), intent(in) :: self     !! the buffer law
      real(wp), intent(in) :: s          !! stroke [m]
      real(wp), intent(in) :: s_dot      !! stroke rate [m/s]
      real(wp), intent(in) :: s_hismin   !! most negative stroke reached so far [m]
      real(wp), intent(in) :: s_hismax   !! most positive stroke reached so far [m]
      real(wp), intent(out) :: f_pos     !! bound against motion toward +s [N], >= 0
      real(wp), intent(out) :: f_neg     !! bound against motion toward -s [N], >= 0
    end subroutine resistance_iface
    !> Stroke capacity in each direction.
    pure subroutine capacity_iface(self, cap_pos, cap_neg)
      import :: buffer_law_t, wp
      class(buffer_law_t), intent(in) :: self     !! the buffer law
      real(wp), intent(out) :: cap_pos   !! stroke available toward +s [m]
      real(wp), intent(out) :: cap_neg   !! stroke available toward -s [m] (0: rigid stop at s = 0)
    end subroutine capacity_iface
    !> The piece of the law's force-stroke curve at stroke s: an integer that changes exactly where
    !! the crush force jumps or a stop begins (a stage end, the end of the stroke), so that the
    !! adaptive integrator can locate those instants as events. Its values mean nothing else.
    pure integer function segment_iface(self, s)
      import :: buffer_law_t, wp
      class(buffer_law_t), intent(in) :: self     !! the buffer law
      real(wp), intent(in) :: s          !! stroke [m]
    end function segment_iface
  end interface

  !> A buffer law with a stiff end-of-stroke stop (spring and damper beyond the stroke capacity).
  type, abstract, extends(buffer_law_t) :: stop_buffer_t
    real(wp) :: k_stop = 1.0e9_wp            !! end-of-stroke stop stiffness [N/m]
    real(wp) :: c_stop = 1.0e5_wp            !! end-of-stroke stop damping [N s/m]
  end type stop_buffer_t

  !> Primary strut: multi-stage honeycomb crushed in shortening (eq. 21); rigid stop against
  !! extension beyond the original length.
  type, extends(stop_buffer_t) :: primary_honeycomb_t
    integer :: n_stages = 2                  !! number of stages [-]
    real(wp) :: stage_force(5) = 0.0_wp      !! crush force of each stage [N]
    real(wp) :: stage_end(5) = 0.0_wp        !! stroke at which each stage ends [m]
  contains
    procedure :: resistance => primary_resistance  !! stage crush force in shortening, rigid stop in extension [N]
    procedure :: capacity => primary_capacity      !! end of the last stage in shortening, 0 in extension [m]
    procedure :: segment => primary_segment        !! stage number, n_stages + 1 on the stop [-]
    procedure :: crush_levels => primary_crush_levels  !! stage k's crush force against shortening [N]
  end type primary_honeycomb_t

  !> Secondary strut: two-direction honeycomb (eq. 22), levels named by the motion they resist.
  type, extends(stop_buffer_t) :: secondary_honeycomb_t
    real(wp) :: f_lengthening = 43000.0_wp   !! crush force resisting lengthening (+s) [N]
    real(wp) :: f_shortening = 30000.0_wp    !! crush force resisting shortening (-s) [N]
    real(wp) :: stroke_lengthening = 0.27_wp !! stroke available toward +s [m]
    real(wp) :: stroke_shortening = 0.27_wp  !! stroke available toward -s [m]
  contains
    procedure :: resistance => secondary_resistance  !! crush force in lengthening and in shortening [N]
    procedure :: capacity => secondary_capacity      !! stroke_lengthening and stroke_shortening [m]
    procedure :: segment => secondary_segment        !! 0 within the stroke, +1 / -1 on a stop [-]
    procedure :: crush_levels => secondary_crush_levels  !! the crush forces against lengthening and shortening [N]
  end type secondary_honeycomb_t

contains

  !> The strokes between which the buffer offers no resistance in either direction (the crushed
  !! range of eqs. 21-22; the event locator's switching function of a free strut): a stroke beyond
  !! hi meets the bound toward +s, below lo the bound toward -s, as the laws' resistance decides
  !! (tolerance history_tol). A law without stroke toward -s (capacity 0) has its rigid stop at s = 0.
  pure subroutine history_free_range(self, s_hismin, s_hismax, lo, hi)
    class(buffer_law_t), intent(in) :: self     !! the buffer law
    real(wp), intent(in) :: s_hismin   !! most negative stroke reached so far [m]
    real(wp), intent(in) :: s_hismax   !! most positive stroke reached so far [m]
    real(wp), intent(out) :: lo        !! lower end of the free range [m]
    real(wp), intent(out) :: hi        !! upper end [m]
    real(wp) :: cap_pos, cap_neg
    call self%capacity(cap_pos, cap_neg)
    lo = s_hismin
    if (cap_neg <= 0.0_wp) lo = max(0.0_wp, s_hismin)
    lo = lo + history_tol
    hi = s_hismax - history_tol
  end subroutine history_free_range

  !> The law's constant crush forces, what reports draw as its levels: level j is the bound
  !! force(j) against motion toward +s (toward(j) = +1) or -s (-1), named name(j); the first n are
  !! set (n <= size(force)). Default: the bounds the law offers at the nominal state (stroke 0,
  !! nothing crushed, at rest) in each direction where it has a finite, non-zero one, named
  !! `initial +s`, `initial -s`: the forces at which a strut first gives way.
  pure subroutine initial_crush_levels(self, force, toward, name, n)
    class(buffer_law_t), intent(in) :: self     !! the buffer law
    real(wp), intent(out) :: force(:)           !! crush force of each level, >= 0 [N]
    integer, intent(out) :: toward(:)           !! +1: it resists motion toward +s, -1 toward -s [-]
    character(len=*), intent(out) :: name(:)    !! what each level is, e.g. `stage 1` [-]
    integer, intent(out) :: n                   !! number of levels [-]
    real(wp) :: f(2)
    integer :: j
    character(len=10), parameter :: names(2) = ['initial +s', 'initial -s']
    force = 0.0_wp
    toward = 0
    name = ''
    n = 0
    call self%resistance(0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, f(1), f(2))
    do j = 1, 2
      if (f(j) > 0.0_wp .and. f(j) < rigid_force .and. n < min(size(force), size(toward), size(name))) then
        n = n + 1
        force(n) = f(j)
        toward(n) = 3 - 2*j
        name(n) = names(j)
      end if
    end do
  end subroutine initial_crush_levels

  !> Primary levels: the crush force of each stage (eq. 21) against shortening, `stage 1` ...
  pure subroutine primary_crush_levels(self, force, toward, name, n)
    class(primary_honeycomb_t), intent(in) :: self  !! the buffer law
    real(wp), intent(out) :: force(:)           !! crush force of each stage [N]
    integer, intent(out) :: toward(:)           !! +1: against shortening [-]
    character(len=*), intent(out) :: name(:)    !! `stage k` [-]
    integer, intent(out) :: n                   !! number of stages reported [-]
    integer :: k
    force = 0.0_wp
    toward = 0
    name = ''
    n = min(self%n_stages, size(force), size(toward), size(name))
    do k = 1, n
      force(k) = self%stage_force(k)
      toward(k) = 1
      write (name(k), '(a,i0)') 'stage ', k
    end do
  end subroutine primary_crush_levels

  !> Secondary levels (eq. 22): `lengthening` against +s, `shortening` against -s.
  pure subroutine secondary_crush_levels(self, force, toward, name, n)
    class(secondary_honeycomb_t), intent(in) :: self  !! the buffer law
    real(wp), intent(out) :: force(:)           !! crush forces [N]
    integer, intent(out) :: toward(:)           !! +1 against lengthening, -1 against shortening [-]
    character(len=*), intent(out) :: name(:)    !! `lengthening`, `shortening` [-]
    integer, intent(out) :: n                   !! 2, or fewer when the arrays are shorter [-]
    force = 0.0_wp
    toward = 0
    name = ''
    n = min(2, size(force), size(toward), size(name))
    if (n >= 1) then
      force(1) = self%f_lengthening
      toward(1) = 1
      name(1) = 'lengthening'
    end if
    if (n >= 2) then
      force(2) = self%f_shortening
      toward(2) = -1
      name(2) = 'shortening'
    end if
  end subroutine secondary_crush_levels

  !> Primary bounds (eq. 21): the current stage's crush force against shortening at the crush front
  !! (plus the stop beyond the last stage), 0 inside the crushed range; rigid against extension at s <= 0.
  pure subroutine primary_resistance(self, s, s_dot, s_hismin, s_hismax, f_pos, f_neg)
    class(primary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(in) :: s          !! stroke (shortening positive) [m]
    real(wp), intent(in) :: s_dot      !! stroke rate [m/s]
    real(wp), intent(in) :: s_hismin   !! smallest stroke reached (the primary never crushes in extension: <= 0) [m]
    real(wp), intent(in) :: s_hismax   !! largest stroke reached so far [m]
    real(wp), intent(out) :: f_pos     !! bound against further shortening [N]
    real(wp), intent(out) :: f_neg     !! bound against extension [N]
    integer :: k
    real(wp) :: cap
    f_pos = 0.0_wp
    if (s >= s_hismax - history_tol) then
      cap = self%stage_end(self%n_stages)
      if (s <= cap) then
        f_pos = self%stage_force(self%n_stages)
        do k = 1, self%n_stages
          if (s <= self%stage_end(k)) then
            f_pos = self%stage_force(k)
            exit
          end if
        end do
      else
        f_pos = with_stop(self%stage_force(self%n_stages), self%k_stop, self%c_stop, s - cap, s_dot)
      end if
    end if
    f_neg = 0.0_wp
    if (s <= max(0.0_wp, s_hismin) + history_tol) f_neg = rigid_force
  end subroutine primary_resistance

  !> The bound on an end-of-stroke stop: the last crush force plus the stop's spring and damper,
  !! f_last + k_stop over + c_stop max(rate, 0) (in this order of the sums).
  pure function with_stop(f_last, k_stop, c_stop, over, rate) result(f)
    real(wp), intent(in) :: f_last   !! crush force at the end of the stroke [N]
    real(wp), intent(in) :: k_stop   !! stop stiffness [N/m]
    real(wp), intent(in) :: c_stop   !! stop damping [N s/m]
    real(wp), intent(in) :: over     !! stroke beyond the capacity, > 0 [m]
    real(wp), intent(in) :: rate     !! stroke rate toward the stop [m/s]
    real(wp) :: f                    !! bound [N]
    f = f_last + k_stop*over + c_stop*max(rate, 0.0_wp)
  end function with_stop

  !> Primary capacity: the end of the last stage in shortening, none in extension.
  pure subroutine primary_capacity(self, cap_pos, cap_neg)
    class(primary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(out) :: cap_pos   !! stroke capacity in shortening [m]
    real(wp), intent(out) :: cap_neg   !! 0: rigid stop at the original length [m]
    cap_pos = self%stage_end(self%n_stages)
    cap_neg = 0.0_wp
  end subroutine primary_capacity

  !> Stage k (1..n_stages) while s <= stage_end(k), n_stages + 1 on the end-of-stroke stop.
  pure integer function primary_segment(self, s) result(seg)
    class(primary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(in) :: s          !! stroke (shortening positive) [m]
    integer :: k
    seg = self%n_stages + 1
    do k = 1, self%n_stages
      if (s <= self%stage_end(k)) then
        seg = k
        return
      end if
    end do
  end function primary_segment

  !> Secondary bounds (eq. 22): f_lengthening / f_shortening at the crush front of each direction
  !! (plus the stop beyond the stroke), 0 inside the crushed range.
  pure subroutine secondary_resistance(self, s, s_dot, s_hismin, s_hismax, f_pos, f_neg)
    class(secondary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(in) :: s          !! stroke (lengthening positive) [m]
    real(wp), intent(in) :: s_dot      !! stroke rate [m/s]
    real(wp), intent(in) :: s_hismin   !! most negative stroke reached so far [m]
    real(wp), intent(in) :: s_hismax   !! most positive stroke reached so far [m]
    real(wp), intent(out) :: f_pos     !! bound against lengthening [N]
    real(wp), intent(out) :: f_neg     !! bound against shortening [N]
    f_pos = 0.0_wp
    if (s >= s_hismax - history_tol) then
      f_pos = self%f_lengthening
      if (s > self%stroke_lengthening) f_pos = with_stop(f_pos, self%k_stop, self%c_stop, s - self%stroke_lengthening, s_dot)
    end if
    f_neg = 0.0_wp
    if (s <= s_hismin + history_tol) then
      f_neg = self%f_shortening
      if (-s > self%stroke_shortening) f_neg = with_stop(f_neg, self%k_stop, self%c_stop, -s - self%stroke_shortening, -s_dot)
    end if
  end subroutine secondary_resistance

  !> Secondary capacity: stroke_lengthening toward +s, stroke_shortening toward -s.
  pure subroutine secondary_capacity(self, cap_pos, cap_neg)
    class(secondary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(out) :: cap_pos   !! stroke available in lengthening [m]
    real(wp), intent(out) :: cap_neg   !! stroke available in shortening [m]
    cap_pos = self%stroke_lengthening
    cap_neg = self%stroke_shortening
  end subroutine secondary_capacity

  !> 0 within the stroke, +1 on the lengthening stop, -1 on the shortening stop.
  pure integer function secondary_segment(self, s) result(seg)
    class(secondary_honeycomb_t), intent(in) :: self!! the buffer law
    real(wp), intent(in) :: s          !! stroke (lengthening positive) [m]
    seg = 0
    if (s > self%stroke_lengthening) seg = 1
    if (-s > self%stroke_shortening) seg = -1
  end function secondary_segment

end module landyn_buffer
