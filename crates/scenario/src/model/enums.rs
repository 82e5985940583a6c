//! The enumerations of the OpenSCENARIO 1.3 XSD (simple types with `xsd:enumeration`), with
//! the literals deprecated since 1.0–1.2 read as their 1.3 replacement where one exists
//! (`overwrite` → `override`, `cartesianDistance` → `euclidianDistance`). `ParameterType` is
//! [`crate::expr::ValueType`].

use crate::attr::xsd_enum;

xsd_enum! {
    /// Which rotation angle a condition compares (AngleCondition, RelativeAngleCondition). XSD
    /// `AngleType`.
    AngleType {
        /// `heading`.
        Heading = "heading",
        /// `pitch`.
        Pitch = "pitch",
        /// `roll`.
        Roll = "roll",
    }
}

xsd_enum! {
    /// Positions of an automatic gearbox selector (OverrideGearAction). XSD `AutomaticGearType`.
    AutomaticGearType {
        /// `n`.
        N = "n",
        /// `p`.
        P = "p",
        /// `r`.
        R = "r",
        /// `d`.
        D = "d",
    }
}

xsd_enum! {
    /// Cloudiness (deprecated since 1.2 in favour of FractionalCloudCover). XSD `CloudState`.
    CloudState {
        /// `cloudy`.
        Cloudy = "cloudy",
        /// `free`.
        Free = "free",
        /// `overcast`.
        Overcast = "overcast",
        /// `rainy`.
        Rainy = "rainy",
        /// `skyOff`.
        SkyOff = "skyOff",
    }
}

xsd_enum! {
    /// Basic colour of an entity (Color). XSD `ColorType`.
    ColorType {
        /// `other`.
        Other = "other",
        /// `red`.
        Red = "red",
        /// `yellow`.
        Yellow = "yellow",
        /// `green`.
        Green = "green",
        /// `blue`.
        Blue = "blue",
        /// `violet`.
        Violet = "violet",
        /// `orange`.
        Orange = "orange",
        /// `brown`.
        Brown = "brown",
        /// `black`.
        Black = "black",
        /// `grey`.
        Grey = "grey",
        /// `white`.
        White = "white",
    }
}

xsd_enum! {
    /// When a condition reports true: on its level (`none`) or on a change of it ("Conditions and
    /// triggers"). XSD `ConditionEdge`.
    ConditionEdge {
        /// `falling`.
        Falling = "falling",
        /// `none`.
        None = "none",
        /// `rising`.
        Rising = "rising",
        /// `risingOrFalling`.
        RisingOrFalling = "risingOrFalling",
    }
}

xsd_enum! {
    /// Control domains a controller or ActivateControllerAction addresses. XSD `ControllerType`.
    ControllerType {
        /// `lateral`.
        Lateral = "lateral",
        /// `longitudinal`.
        Longitudinal = "longitudinal",
        /// `lighting`.
        Lighting = "lighting",
        /// `animation`.
        Animation = "animation",
        /// `movement`.
        Movement = "movement",
        /// `appearance`.
        Appearance = "appearance",
        /// `all`.
        All = "all",
    }
}

xsd_enum! {
    /// Coordinate system a distance or position is measured in. XSD `CoordinateSystem`.
    CoordinateSystem {
        /// `entity`.
        Entity = "entity",
        /// `lane`.
        Lane = "lane",
        /// `road`.
        Road = "road",
        /// `trajectory`.
        Trajectory = "trajectory",
        /// `world`.
        World = "world",
    }
}

xsd_enum! {
    /// Axis of a directional measurement (AccelerationCondition, SpeedCondition). XSD
    /// `DirectionalDimension`.
    DirectionalDimension {
        /// `longitudinal`.
        Longitudinal = "longitudinal",
        /// `lateral`.
        Lateral = "lateral",
        /// `vertical`.
        Vertical = "vertical",
    }
}

xsd_enum! {
    /// What a transition's `value` measures: a distance (m), a rate (per s) or a time (s). XSD
    /// `DynamicsDimension`.
    DynamicsDimension {
        /// `distance`.
        Distance = "distance",
        /// `rate`.
        Rate = "rate",
        /// `time`.
        Time = "time",
    }
}

xsd_enum! {
    /// Shape of a transition function (TransitionDynamics). XSD `DynamicsShape`.
    DynamicsShape {
        /// `cubic`.
        Cubic = "cubic",
        /// `linear`.
        Linear = "linear",
        /// `sinusoidal`.
        Sinusoidal = "sinusoidal",
        /// `step`.
        Step = "step",
    }
}

xsd_enum! {
    /// How a trajectory or lateral distance is followed. XSD `FollowingMode`.
    FollowingMode {
        /// `follow`.
        Follow = "follow",
        /// `position`.
        Position = "position",
    }
}

xsd_enum! {
    /// Cloud cover in oktas (1.2+). XSD `FractionalCloudCover`.
    FractionalCloudCover {
        /// `zeroOktas`.
        ZeroOktas = "zeroOktas",
        /// `oneOktas`.
        OneOktas = "oneOktas",
        /// `twoOktas`.
        TwoOktas = "twoOktas",
        /// `threeOktas`.
        ThreeOktas = "threeOktas",
        /// `fourOktas`.
        FourOktas = "fourOktas",
        /// `fiveOktas`.
        FiveOktas = "fiveOktas",
        /// `sixOktas`.
        SixOktas = "sixOktas",
        /// `sevenOktas`.
        SevenOktas = "sevenOktas",
        /// `eightOktas`.
        EightOktas = "eightOktas",
        /// `nineOktas`.
        NineOktas = "nineOktas",
    }
}

xsd_enum! {
    /// Required lateral side relative to a referenced entity (LateralDistanceAction, 1.3
    /// displacement). XSD `LateralDisplacement`.
    LateralDisplacement {
        /// `any`.
        Any = "any",
        /// `leftToReferencedEntity`.
        LeftToReferencedEntity = "leftToReferencedEntity",
        /// `rightToReferencedEntity`.
        RightToReferencedEntity = "rightToReferencedEntity",
    }
}

xsd_enum! {
    /// State of a light (LightState). XSD `LightMode`.
    LightMode {
        /// `on`.
        On = "on",
        /// `off`.
        Off = "off",
        /// `flashing`.
        Flashing = "flashing",
    }
}

xsd_enum! {
    /// Required longitudinal order relative to a referenced entity (LongitudinalDistanceAction).
    /// XSD `LongitudinalDisplacement`.
    LongitudinalDisplacement {
        /// `any`.
        Any = "any",
        /// `trailingReferencedEntity`.
        TrailingReferencedEntity = "trailingReferencedEntity",
        /// `leadingReferencedEntity`.
        LeadingReferencedEntity = "leadingReferencedEntity",
    }
}

xsd_enum! {
    /// Category of a MiscObject, as in OpenDRIVE objects. XSD `MiscObjectCategory`.
    MiscObjectCategory {
        /// `barrier`.
        Barrier = "barrier",
        /// `building`.
        Building = "building",
        /// `crosswalk`.
        Crosswalk = "crosswalk",
        /// `gantry`.
        Gantry = "gantry",
        /// `none`.
        None = "none",
        /// `obstacle`.
        Obstacle = "obstacle",
        /// `parkingSpace`.
        ParkingSpace = "parkingSpace",
        /// `patch`.
        Patch = "patch",
        /// `pole`.
        Pole = "pole",
        /// `railing`.
        Railing = "railing",
        /// `roadMark`.
        RoadMark = "roadMark",
        /// `soundBarrier`.
        SoundBarrier = "soundBarrier",
        /// `streetLamp`.
        StreetLamp = "streetLamp",
        /// `trafficIsland`.
        TrafficIsland = "trafficIsland",
        /// `tree`.
        Tree = "tree",
        /// `vegetation`.
        Vegetation = "vegetation",
        /// `wind` (deprecated).
        Wind = "wind",
    }
}

xsd_enum! {
    /// Kind of entity (ByType, ByObjectType). XSD `ObjectType`.
    ObjectType {
        /// `miscellaneous`.
        Miscellaneous = "miscellaneous",
        /// `pedestrian`.
        Pedestrian = "pedestrian",
        /// `vehicle`.
        Vehicle = "vehicle",
        /// `external`.
        External = "external",
    }
}

xsd_enum! {
    /// Category of a Pedestrian. XSD `PedestrianCategory`.
    PedestrianCategory {
        /// `animal`.
        Animal = "animal",
        /// `pedestrian`.
        Pedestrian = "pedestrian",
        /// `wheelchair`.
        Wheelchair = "wheelchair",
    }
}

xsd_enum! {
    /// Gestures of a pedestrian (PedestrianGesture, 1.2+). XSD `PedestrianGestureType`.
    PedestrianGestureType {
        /// `phoneCallRightHand`.
        PhoneCallRightHand = "phoneCallRightHand",
        /// `phoneCallLeftHand`.
        PhoneCallLeftHand = "phoneCallLeftHand",
        /// `phoneTextRightHand`.
        PhoneTextRightHand = "phoneTextRightHand",
        /// `phoneTextLeftHand`.
        PhoneTextLeftHand = "phoneTextLeftHand",
        /// `wavingRightArm`.
        WavingRightArm = "wavingRightArm",
        /// `wavingLeftArm`.
        WavingLeftArm = "wavingLeftArm",
        /// `umbrellaRightHand`.
        UmbrellaRightHand = "umbrellaRightHand",
        /// `umbrellaLeftHand`.
        UmbrellaLeftHand = "umbrellaLeftHand",
        /// `crossArms`.
        CrossArms = "crossArms",
        /// `coffeeRightHand`.
        CoffeeRightHand = "coffeeRightHand",
        /// `coffeeLeftHand`.
        CoffeeLeftHand = "coffeeLeftHand",
        /// `sandwichRightHand`.
        SandwichRightHand = "sandwichRightHand",
        /// `sandwichLeftHand`.
        SandwichLeftHand = "sandwichLeftHand",
    }
}

xsd_enum! {
    /// Motions of a pedestrian (PedestrianAnimation, 1.2+). XSD `PedestrianMotionType`.
    PedestrianMotionType {
        /// `standing`.
        Standing = "standing",
        /// `sitting`.
        Sitting = "sitting",
        /// `lying`.
        Lying = "lying",
        /// `squatting`.
        Squatting = "squatting",
        /// `walking`.
        Walking = "walking",
        /// `running`.
        Running = "running",
        /// `reeling`.
        Reeling = "reeling",
        /// `crawling`.
        Crawling = "crawling",
        /// `cycling`.
        Cycling = "cycling",
        /// `jumping`.
        Jumping = "jumping",
        /// `ducking`.
        Ducking = "ducking",
        /// `bendingDown`.
        BendingDown = "bendingDown",
    }
}

xsd_enum! {
    /// Kind of precipitation. XSD `PrecipitationType`.
    PrecipitationType {
        /// `dry`.
        Dry = "dry",
        /// `rain`.
        Rain = "rain",
        /// `snow`.
        Snow = "snow",
    }
}

xsd_enum! {
    /// What starting an Event does to other running Events of its Maneuver (§8.4, storyboard
    /// execution). XSD `Priority`.
    Priority {
        /// `override`.
        Override = "override" | "overwrite",
        /// `parallel`.
        Parallel = "parallel",
        /// `skip`.
        Skip = "skip",
    }
}

xsd_enum! {
    /// Whether a time or value is absolute or relative. XSD `ReferenceContext`.
    ReferenceContext {
        /// `absolute`.
        Absolute = "absolute",
        /// `relative`.
        Relative = "relative",
    }
}

xsd_enum! {
    /// How a relative distance is measured. XSD `RelativeDistanceType`.
    RelativeDistanceType {
        /// `lateral`.
        Lateral = "lateral",
        /// `longitudinal`.
        Longitudinal = "longitudinal",
        /// `euclidianDistance`.
        EuclidianDistance = "euclidianDistance" | "cartesianDistance",
    }
}

xsd_enum! {
    /// Role of a vehicle or pedestrian in traffic (1.2+). XSD `Role`.
    Role {
        /// `none`.
        None = "none",
        /// `ambulance`.
        Ambulance = "ambulance",
        /// `civil`.
        Civil = "civil",
        /// `fire`.
        Fire = "fire",
        /// `military`.
        Military = "military",
        /// `police`.
        Police = "police",
        /// `publicTransport`.
        PublicTransport = "publicTransport",
        /// `roadAssistance`.
        RoadAssistance = "roadAssistance",
    }
}

xsd_enum! {
    /// Strategy for choosing a path through a Waypoint. XSD `RouteStrategy`.
    RouteStrategy {
        /// `fastest`.
        Fastest = "fastest",
        /// `leastIntersections`.
        LeastIntersections = "leastIntersections",
        /// `random`.
        Random = "random",
        /// `shortest`.
        Shortest = "shortest",
    }
}

xsd_enum! {
    /// How a route between two positions is chosen for a distance (1.2+). XSD `RoutingAlgorithm`.
    RoutingAlgorithm {
        /// `assignedRoute`.
        AssignedRoute = "assignedRoute",
        /// `fastest`.
        Fastest = "fastest",
        /// `leastIntersections`.
        LeastIntersections = "leastIntersections",
        /// `shortest`.
        Shortest = "shortest",
        /// `undefined`.
        Undefined = "undefined",
    }
}

xsd_enum! {
    /// Comparison rule of conditions and value constraints. XSD `Rule`.
    Rule {
        /// `equalTo`.
        EqualTo = "equalTo",
        /// `greaterThan`.
        GreaterThan = "greaterThan",
        /// `lessThan`.
        LessThan = "lessThan",
        /// `greaterOrEqual`.
        GreaterOrEqual = "greaterOrEqual",
        /// `lessOrEqual`.
        LessOrEqual = "lessOrEqual",
        /// `notEqualTo`.
        NotEqualTo = "notEqualTo",
    }
}

xsd_enum! {
    /// Whether a relative target speed is a difference or a factor. XSD `SpeedTargetValueType`.
    SpeedTargetValueType {
        /// `delta`.
        Delta = "delta",
        /// `factor`.
        Factor = "factor",
    }
}

xsd_enum! {
    /// States and transitions of storyboard elements (§8.4). XSD `StoryboardElementState`.
    StoryboardElementState {
        /// `completeState`.
        CompleteState = "completeState",
        /// `endTransition`.
        EndTransition = "endTransition",
        /// `runningState`.
        RunningState = "runningState",
        /// `skipTransition`.
        SkipTransition = "skipTransition",
        /// `standbyState`.
        StandbyState = "standbyState",
        /// `startTransition`.
        StartTransition = "startTransition",
        /// `stopTransition`.
        StopTransition = "stopTransition",
    }
}

xsd_enum! {
    /// Kinds of storyboard elements. XSD `StoryboardElementType`.
    StoryboardElementType {
        /// `act`.
        Act = "act",
        /// `action`.
        Action = "action",
        /// `event`.
        Event = "event",
        /// `maneuver`.
        Maneuver = "maneuver",
        /// `maneuverGroup`.
        ManeuverGroup = "maneuverGroup",
        /// `story`.
        Story = "story",
    }
}

xsd_enum! {
    /// Whether any or all triggering entities must meet an entity condition. XSD
    /// `TriggeringEntitiesRule`.
    TriggeringEntitiesRule {
        /// `all`.
        All = "all",
        /// `any`.
        Any = "any",
    }
}

xsd_enum! {
    /// Category of a Vehicle. XSD `VehicleCategory`.
    VehicleCategory {
        /// `bicycle`.
        Bicycle = "bicycle",
        /// `bus`.
        Bus = "bus",
        /// `car`.
        Car = "car",
        /// `motorbike`.
        Motorbike = "motorbike",
        /// `semitrailer`.
        Semitrailer = "semitrailer",
        /// `trailer`.
        Trailer = "trailer",
        /// `train`.
        Train = "train",
        /// `tram`.
        Tram = "tram",
        /// `truck`.
        Truck = "truck",
        /// `van`.
        Van = "van",
    }
}

xsd_enum! {
    /// Movable components of a vehicle (VehicleComponent, 1.2+). XSD `VehicleComponentType`.
    VehicleComponentType {
        /// `hood`.
        Hood = "hood",
        /// `trunk`.
        Trunk = "trunk",
        /// `doorFrontRight`.
        DoorFrontRight = "doorFrontRight",
        /// `doorFrontLeft`.
        DoorFrontLeft = "doorFrontLeft",
        /// `doorRearRight`.
        DoorRearRight = "doorRearRight",
        /// `doorRearLeft`.
        DoorRearLeft = "doorRearLeft",
        /// `windowFrontRight`.
        WindowFrontRight = "windowFrontRight",
        /// `windowFrontLeft`.
        WindowFrontLeft = "windowFrontLeft",
        /// `windowRearRight`.
        WindowRearRight = "windowRearRight",
        /// `windowRearLeft`.
        WindowRearLeft = "windowRearLeft",
        /// `sideMirrors`.
        SideMirrors = "sideMirrors",
        /// `sideMirrorRight`.
        SideMirrorRight = "sideMirrorRight",
        /// `sideMirrorLeft`.
        SideMirrorLeft = "sideMirrorLeft",
    }
}

xsd_enum! {
    /// Lights of a vehicle (VehicleLight, 1.2+). XSD `VehicleLightType`.
    VehicleLightType {
        /// `daytimeRunningLights`.
        DaytimeRunningLights = "daytimeRunningLights",
        /// `lowBeam`.
        LowBeam = "lowBeam",
        /// `highBeam`.
        HighBeam = "highBeam",
        /// `fogLights`.
        FogLights = "fogLights",
        /// `fogLightsFront`.
        FogLightsFront = "fogLightsFront",
        /// `fogLightsRear`.
        FogLightsRear = "fogLightsRear",
        /// `brakeLights`.
        BrakeLights = "brakeLights",
        /// `warningLights`.
        WarningLights = "warningLights",
        /// `indicatorLeft`.
        IndicatorLeft = "indicatorLeft",
        /// `indicatorRight`.
        IndicatorRight = "indicatorRight",
        /// `reversingLights`.
        ReversingLights = "reversingLights",
        /// `licensePlateIllumination`.
        LicensePlateIllumination = "licensePlateIllumination",
        /// `specialPurposeLights`.
        SpecialPurposeLights = "specialPurposeLights",
    }
}

xsd_enum! {
    /// Road surface wetness (RoadCondition, 1.2+). XSD `Wetness`.
    Wetness {
        /// `dry`.
        Dry = "dry",
        /// `moist`.
        Moist = "moist",
        /// `wetWithPuddles`.
        WetWithPuddles = "wetWithPuddles",
        /// `lowFlooded`.
        LowFlooded = "lowFlooded",
        /// `highFlooded`.
        HighFlooded = "highFlooded",
    }
}
